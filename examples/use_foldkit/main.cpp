// Generates a Miura-ori, writes it as PMML and reads it back: the smallest program that uses
// foldkit as a library.
#include <iostream>

#include <foldkit/geometry/generators.hpp>
#include <foldkit/io/pmml.hpp>

int main() {
  using namespace foldkit;
  const geometry::CreasePattern miura = geometry::build_or_throw(geometry::generators::miura(3, 5));
  const std::string text = io::write_pmml(miura);
  const geometry::CreasePattern again = geometry::build_or_throw(io::parse_pmml(text, "miura.pmml"));
  std::cout << again.actors().size() << " actors, " << again.joints().size() << " joints\n";
  return again.joints().size() == miura.joints().size() ? 0 : 1;
}
