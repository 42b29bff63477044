#pragma once
/// @file
/// PMML crease patterns (paper Table 1): reading and writing.
#include <optional>
#include <string>
#include <string_view>

#include "foldkit/geometry/crease_pattern.hpp"
#include "foldkit/geometry/pattern_spec.hpp"

namespace foldkit::io {

/// Parses PMML text (paper Table 1) into a spec, unchecked geometrically (build_pattern() does
/// that). The title keeps its inner whitespace; leading and trailing whitespace is trimmed.
/// @param text  the file's content
/// @param name  the file name used in error messages
/// foldkit's extensions for the dynamic model (`<Density>`, `<Gravity>`, `<FixedActor>`, at most
/// one each under `<PMML>`; `<MaxTorque>` per joint) are read into the spec, their ranges left to
/// build_pattern() too.
/// @throws ParseError for anything that is not PMML: unknown elements, missing or repeated
///         fields, non-integer IDs, non-finite numbers, a `<Gravity>` without exactly three
///         numbers, no actor, text that is not UTF-8
geometry::PatternSpec parse_pmml(const std::string& text, const std::string& name);
/// Reads and parses the PMML file at `path`.
/// @throws ParseError when the file cannot be read or is not PMML
geometry::PatternSpec read_pmml_spec(const std::string& path);

/// Reads, parses and builds the PMML file at `path`.
/// @param path     the file
/// @param options  tolerances and repairs of build_pattern()
/// @throws ParseError as read_pmml_spec(), and for a pattern build_pattern() rejects: one
///         ParseError at the line of the first error, whose message says how many more there are
geometry::CreasePattern read_pmml(const std::string& path, const geometry::BuildOptions& options = {});

/// The PMML text of `spec`; an assignment is written only when it is not Unassigned, foldkit's
/// other extensions (`<MaxTorque>`, `<Density>`, `<Gravity>`, `<FixedActor>`) only when set. The
/// title is written so that the file stays valid XML (characters XML forbids become U+FFFD).
/// @throws std::invalid_argument ("…: not a finite number") for a non-finite coordinate, spring
///         or damping constant, maximum torque, density or gravity: a written file never holds NaN
///         or inf
std::string write_pmml(const geometry::PatternSpec& spec);
/// The PMML text of `pattern` (its CreasePattern::to_spec(): vertex coordinates after merging).
std::string write_pmml(const geometry::CreasePattern& pattern);

namespace detail {

/// The PMML `text` read without an XML parser, when it is in the shape write_pmml() writes: an
/// optional `<?xml version="1.0" encoding="UTF-8"?>`, then `<PMML>` holding `<Title>`, the
/// physics extensions, `<Actor>` (`<ID>` then `<Triangle>`s) and `<Joint>` (`<ID>`, `<Coords>`,
/// `<ActorIDs>`, `<SpringConst>`, `<DampConst>`, then perhaps `<Assignment>` and `<MaxTorque>`)
/// in any order; no attribute, comment, entity, carriage return or non-ASCII byte; white space
/// between elements only; each number's text of number characters only; a one-line title. The
/// spec, lines included, is then exactly parse_pmml_xml()'s; std::nullopt when the text is not
/// in that shape or would be refused (the XML reading then decides and reports the error).
std::optional<geometry::PatternSpec> read_plain_pmml(std::string_view text);

/// parse_pmml() by its XML reading alone (tinyxml2 and the strict checks of XmlInput): what
/// parse_pmml() does with any text read_plain_pmml() declines, and the oracle it is tested against.
/// @throws ParseError as parse_pmml()
geometry::PatternSpec parse_pmml_xml(const std::string& text, const std::string& name);

}  // namespace detail

}  // namespace foldkit::io
