// Mesh pictures: the zoomed inset of a window, the legend, the angle histogram.
#include <pdd/io/angle_histogram.hpp>
#include <pdd/io/svg.hpp>

#include <gtest/gtest.h>

#include "test_files.hpp"

#include <string>

namespace mesh_pictures_test {
namespace {

std::size_t occurrences(const std::string& s, const std::string& what) {
  std::size_t n = 0;
  for (std::size_t p = s.find(what); p != std::string::npos; p = s.find(what, p + 1))
    ++n;
  return n;
}

} // namespace

TEST(MeshPictures, WindowInsetShowsOnlyItsTriangles) {
  const auto dir = pdd::test::fresh_dir("pictures");
  const auto m = pdd::test::small_mesh();
  pdd::svg_options o;
  o.window = pdd::svg_window{0.0, 0.0, 0.4, 0.4}; // meets triangles 0 and 3 of subdomain 0 only
  pdd::write_svg(dir / "w.svg", m, o);
  const std::string s = pdd::test::read_text(dir / "w.svg");
  // all 8 triangles are drawn on the picture (small mesh) and no subdomain outline
  EXPECT_EQ(occurrences(s, "fill-rule=\"nonzero\""), 0u);
  const std::string inset = s.substr(s.find("<g clip-path"));
  const std::size_t d = inset.find(" d=\"") + 4;
  EXPECT_EQ(occurrences(inset.substr(d, inset.find('"', d) - d), "M"), 2u); // two triangles
  EXPECT_NE(s.find("inset: x 0.0000 to 0.4000, y 0.0000 to 0.4000"), std::string::npos);
  // the window is 0.4 wide: the inset is as tall as the picture is wide
  EXPECT_NE(s.find("height=\"1510.00\""), std::string::npos) << s.substr(0, 300);
  EXPECT_NE(s.find("smallest angle 45.00 deg"), std::string::npos);
  o.window = pdd::svg_window{1, 1, 0, 2};
  EXPECT_THROW(pdd::write_svg(dir / "bad.svg", m, o), pdd::error);
  o.window.reset();
  o.legend = false;
  pdd::write_svg(dir / "n.svg", m, o);
  const std::string n = pdd::test::read_text(dir / "n.svg");
  EXPECT_EQ(n.find("<text"), std::string::npos);
  EXPECT_EQ(n.find("clip-path"), std::string::npos); // small mesh, no window: no inset
}

TEST(MeshPictures, AngleHistogram) {
  const auto dir = pdd::test::fresh_dir("histogram");
  const auto m = pdd::test::small_mesh(); // 8 right isosceles triangles: 16 x 45, 8 x 90
  pdd::write_angle_histogram_svg(dir / "h.svg", m);
  const std::string s = pdd::test::read_text(dir / "h.svg");
  EXPECT_NE(s.find("Angles of 8 triangles (1-degree bins; fullest bin 16)"), std::string::npos);
  EXPECT_NE(s.find("smallest 45.00"), std::string::npos);
  EXPECT_NE(s.find("largest 90.00"), std::string::npos);
  // two bars: 45 deg at full height (240 px), 90 deg at half
  const std::string bars = s.substr(s.find("fill=\"#1f77b4\" d=\""));
  EXPECT_EQ(occurrences(bars.substr(0, bars.find("\"/>")), "Z"), 2u);
  EXPECT_NE(bars.find("v-240.00"), std::string::npos);
  EXPECT_NE(bars.find("v-120.00"), std::string::npos);
  if (pdd::test::python_has("xml.etree.ElementTree")) {
    std::string log;
    EXPECT_EQ(pdd::test::run_python(dir,
                                    "import sys, xml.etree.ElementTree as ET\n"
                                    "for f in sys.argv[1:]: ET.parse(f)\n",
                                    (dir / "h.svg").string(), log),
              0)
        << log;
  }
}

TEST(MeshPictures, ShadeByAreaShowsTheGrading) {
  const auto dir = pdd::test::fresh_dir("shade");
  auto m = pdd::test::small_mesh();
  m.vertices[6] = {0.2, 0.2}; // subdomain 0: areas 0.1, 0.4, 0.4, 0.1; subdomain 1: 0.25 each
  pdd::svg_options o;
  pdd::write_svg(dir / "plain.svg", m, o);
  const std::string shade = "fill=\"#000000\" fill-opacity=";
  EXPECT_EQ(pdd::test::read_text(dir / "plain.svg").find(shade), std::string::npos);
  o.shade_by_area = true;
  pdd::write_svg(dir / "s.svg", m, o);
  const std::string s = pdd::test::read_text(dir / "s.svg");
  // both subdomains keep their own fill
  EXPECT_EQ(occurrences(s, "stroke=\"none\""), 2u + 2u); // 2 subdomain fills + 2 shade steps
  // 8 steps over log(0.4 / 0.1): 0.1 in step 0 (opacity 0.5), 0.25 in step 5 (0.5 * 2 / 7),
  // 0.4 in the last step (not shaded)
  const auto triangles_at = [&](const std::string& opacity) {
    const std::size_t p = s.find(shade + "\"" + opacity + "\"");
    if (p == std::string::npos) return std::size_t{0};
    const std::size_t d = s.find(" d=\"", p) + 4;
    return occurrences(s.substr(d, s.find('"', d) - d), "M");
  };
  EXPECT_EQ(triangles_at("0.500"), 2u);
  EXPECT_EQ(triangles_at("0.143"), 4u);
  EXPECT_EQ(occurrences(s, shade), 2u);
  EXPECT_NE(s.find("shade: triangle area 0.1 (darkest) to 0.4 (none), log scale"),
            std::string::npos);
}

} // namespace mesh_pictures_test
