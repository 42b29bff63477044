#pragma once
// The FOLD text of the imported scenes (bench/data, compiled in by bench/CMakeLists.txt).

namespace foldkit::bench::detail {

/// osbo/rigid-origami's birdBase.fold (MIT).
const char* bird_base_fold();
/// robbykraft/Origami's resch-tess.fold (MIT).
const char* resch_fold();

}  // namespace foldkit::bench::detail
