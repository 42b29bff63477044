// foldkit serve and compressed files (issue 35, item 2): io writes a .gz name compressed, so the
// file API stores the text it is sent compressed, returns the stored bytes with gzip content
// coding (which a browser's fetch undoes), and refuses gzip bytes as a body (they would be
// compressed twice). Oracle: the file on disk, decompressed by `gzip -dc`.
#include <cstdio>
#include <filesystem>

#include <gtest/gtest.h>

#include "cli_runner.hpp"
#include "serve_test_server.hpp"

#include <httplib.h>  // last: its <resolv.h> macros would break headers included after it

namespace {

namespace fs = std::filesystem;
using foldkit::test::foldkit;
using foldkit::test::Server;
using foldkit::test::slurp;

std::string gunzip(const std::string& path) {
  std::string out;
  FILE* pipe = popen(("gzip -dc '" + path + "'").c_str(), "r");
  if (!pipe) return out;
  char buffer[4096];
  for (std::size_t n; (n = fread(buffer, 1, sizeof buffer, pipe)) > 0;) out.append(buffer, n);
  pclose(pipe);
  return out;
}

TEST(ServeGzip, CompressedFilesAreStoredAndSentWithGzipCoding) {
  Server s("gzip");
  ASSERT_GT(s.port(), 0) << s.log();
  ASSERT_EQ(foldkit({"generate", "miura", "--rows", "2", "--cols", "2", "-o", s.root() + "-m2.pmml"}).exit, 0);
  const std::string pmml = slurp(s.root() + "-m2.pmml");
  fs::create_directories(s.path("work"));
  const auto put = s.client().Put("/api/file?path=work/m2.pmml.gz", pmml, "application/xml");
  ASSERT_TRUE(put);
  ASSERT_EQ(put->status, 200) << put->body;
  const std::string stored = slurp(s.path("work/m2.pmml.gz"));
  ASSERT_GE(stored.size(), 2u);
  EXPECT_EQ(stored.substr(0, 2), "\x1f\x8b");  // compressed once
  EXPECT_EQ(gunzip(s.path("work/m2.pmml.gz")), pmml);
  httplib::Client raw("127.0.0.1", s.port());
  raw.set_decompress(false);
  const auto get = raw.Get("/api/file?path=work/m2.pmml.gz");
  ASSERT_TRUE(get);
  EXPECT_EQ(get->status, 200);
  EXPECT_EQ(get->get_header_value("Content-Encoding"), "gzip");
  EXPECT_EQ(get->body, stored);
  const auto info = s.post("info", {{"pattern", "work/m2.pmml.gz"}});  // the verbs read it as the CLI does
  EXPECT_EQ(info->status, 200) << info->body;
  const auto twice = s.client().Put("/api/file?path=work/again.pmml.gz", stored, "application/gzip");
  ASSERT_TRUE(twice);
  EXPECT_EQ(twice->status, 400);
  EXPECT_FALSE(fs::exists(s.path("work/again.pmml.gz")));
}

}  // namespace
