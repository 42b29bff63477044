#pragma once
/// @file
/// File names: how readers and the command line tell formats apart by extension.
#include <string>

namespace foldkit::io {

/// Whether `path` ends with `extension` (e.g. ".pbm"), ignoring ASCII case, so that shape.PBM is
/// a PBM file wherever foldkit looks at extensions.
/// @param path       a file name or path
/// @param extension  the ending to look for, dot included
bool has_extension(const std::string& path, const std::string& extension);

}  // namespace foldkit::io
