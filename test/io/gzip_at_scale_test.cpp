// A compressed round trip at the size users write (issue 35, "Files that fit"): the fold of a
// Miura-ori 100 × 100 as projected folding writes it, every crease at every step, about 90 MB of
// CMML. Compressed, it is a small fraction of that, decompresses (by zlib itself) to the plain
// file's bytes, and reads, a slice at a time, as the same sequence. In the `scale` label.
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>

#include <gtest/gtest.h>

#include "foldkit/geometry/generators.hpp"
#include "foldkit/io/cmml.hpp"
#include "gzip_oracle.hpp"
#include "test_paths.hpp"

namespace {

using namespace foldkit;

constexpr double kPi = 3.14159265358979323846;

std::string bytes_of(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// `steps` events from flat to the uniform fold with the zig-zag creases at 0.9 × 180°, in closed
// form (as test/folding/at_scale_test.cpp folds it): tan(ρ_s/2) = cos φ · tan(ρ_z/2).
geometry::FoldSequence miura_fold(const geometry::CreasePattern& p, int steps) {
  geometry::FoldSequence s;
  s.title = "Miura-ori 100x100 folded";
  for (int k = 1; k <= steps; ++k) {
    const double zigzag = 0.9 * kPi * k / steps;
    const double straight = 2.0 * std::atan(std::cos(kPi / 3.0) * std::tan(zigzag / 2.0));
    geometry::FoldEvent event{k, {}};
    for (const auto& joint : p.joints()) {
      const geometry::Vec2 d = p.vertices()[joint.v[1]] - p.vertices()[joint.v[0]];
      const bool vertical = std::abs(d.x()) < 1e-9 * d.norm();
      const double sign = joint.assignment == geometry::Assignment::Mountain ? 1.0 : -1.0;
      event.folds.push_back({joint.id, sign * (vertical ? straight : zigzag), 0.5236});
    }
    s.events.push_back(std::move(event));
  }
  return s;
}

TEST(AtScale, CompressedMiura100FoldReadsAndWritesAsPlain) {
  const geometry::CreasePattern p = geometry::build_or_throw(geometry::generators::miura(100, 100));
  const geometry::FoldSequence s = miura_fold(p, 40);
  const std::string dir = test::temp_dir();
  io::write_cmml_file(dir + "/m.cmml", s);
  io::write_cmml_file(dir + "/m.cmml.gz", s);
  const auto plain_size = std::filesystem::file_size(dir + "/m.cmml");
  const auto packed_size = std::filesystem::file_size(dir + "/m.cmml.gz");
  std::cout << "Miura 100x100, " << s.events.size() << " events: " << plain_size << " bytes of CMML, " << packed_size
            << " gzip-compressed\n";
  EXPECT_GT(plain_size, 80u << 20);
  EXPECT_LT(packed_size * 8, plain_size) << plain_size << " bytes plain, " << packed_size << " compressed";
  {
    const std::string plain = bytes_of(dir + "/m.cmml");
    ASSERT_EQ(test::gunzip(bytes_of(dir + "/m.cmml.gz")) == plain, true) << "the decompressed bytes differ from the plain file";
  }
  const geometry::FoldSequence a = io::read_cmml(dir + "/m.cmml"), b = io::read_cmml(dir + "/m.cmml.gz");
  ASSERT_EQ(a.events.size(), s.events.size());
  ASSERT_EQ(b.events.size(), a.events.size());
  for (std::size_t e = 0; e < a.events.size(); ++e) {
    ASSERT_EQ(b.events[e].folds.size(), a.events[e].folds.size());
    for (std::size_t f = 0; f < a.events[e].folds.size(); ++f) {
      const auto &x = a.events[e].folds[f], &y = b.events[e].folds[f];
      ASSERT_TRUE(x.joint_id == y.joint_id && x.angle == y.angle && x.speed == y.speed && x.line == y.line)
          << "fold " << f << " of event " << e;
    }
  }
}

}  // namespace
