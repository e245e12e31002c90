// The path player page (record/path_player.hpp): base64 by RFC 4648's test vectors, and a page
// that carries the picture, the paths and an escaped title.
#include "swarm/record/path_player.hpp"

#include <gtest/gtest.h>

#include "swarm_test/files.hpp"
#include "swarm_test/text.hpp"

namespace swarm::record {
namespace {

TEST(PathPlayer, Base64MatchesTheRfcVectors) {
  EXPECT_EQ(base64(""), "");
  EXPECT_EQ(base64("f"), "Zg==");
  EXPECT_EQ(base64("fo"), "Zm8=");
  EXPECT_EQ(base64("foo"), "Zm9v");
  EXPECT_EQ(base64("foob"), "Zm9vYg==");
  EXPECT_EQ(base64("fooba"), "Zm9vYmE=");
  EXPECT_EQ(base64("foobar"), "Zm9vYmFy");
}

TEST(PathPlayer, ThePageCarriesThePictureThePathsAndAnEscapedTitle) {
  const swarm::test::TempDir dir;
  PathPlayer p;
  p.background_png = "foobar";
  p.scale = 8;
  p.height = 4;
  p.colours = {palette_colour(0), palette_colour(1)};
  p.paths = {{{0, 0}, {1, 0}}, {{3, 2}}};
  write_path_player(dir.file("a.html"), "plan <1> & more", p);
  const std::string page = read_file(dir.file("a.html"));
  EXPECT_TRUE(swarm::test::contains(page, "<title>plan &lt;1&gt; &amp; more</title>"));
  EXPECT_TRUE(swarm::test::contains(page, "data:image/png;base64,Zm9vYmFy"));
  EXPECT_TRUE(swarm::test::contains(page, "\"paths\":[[[0,0],[1,0]],[[3,2]]]"));
  EXPECT_TRUE(swarm::test::contains(page, "\"scale\":8"));
}

}  // namespace
}  // namespace swarm::record
