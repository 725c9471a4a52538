// The always-on quality check of pdd-mesh (pdd::check_quality, pdd::quality_check_sink): a
// deliberately lax kernel injected through the library API makes bad triangles, and the check
// names the first one and stops the output before anything is written.
#include "test_support.hpp"

#include <pdd/generate.hpp>
#include <pdd/kernels/cgal/mesher.hpp>
#include <pdd/mesh/quality.hpp>
#include <pdd/mesh/quality_check.hpp>
#include <pdd/mesh/sinks.hpp>
// pdd::generate with a kernel of the test's own: compiled here, not in libpdd
#include <pdd/pipeline/generate_templates.hpp>

#include <gtest/gtest.h>

#include <filesystem>
#include <limits>
#include <string>
#include <vector>

namespace quality_check_test {
namespace {

namespace fs = std::filesystem;

/// A faulty DelaunayMesher: the CGAL kernel without the angle bound (drop_angle) or without
/// the area bound (drop_area), as a kernel that broke its guarantee would behave.
struct lax_mesher {
  bool drop_angle = true;
  bool drop_area = false;
  template <pdd::SizingField S>
  pdd::mesher_result mesh(const pdd::pslg& d, const pdd::mesh_criteria& c, const S& s) const {
    pdd::mesh_criteria lax = c;
    if (drop_angle) lax.min_angle_deg = 0.0;
    if (drop_area) lax.max_area = std::numeric_limits<double>::infinity();
    return pdd::cgal::mesher{}.mesh(d, lax, s);
  }
};
static_assert(pdd::DelaunayMesher<lax_mesher>);

/// A 10 x 1 rectangle: two triangles of 5.7 deg without the angle bound.
pdd::pslg long_rectangle() {
  pdd::pslg g;
  g.add_loop(std::vector<pdd::point>{{0, 0}, {10, 0}, {10, 1}, {0, 1}}, 1);
  return g;
}

pdd::generate_options options(std::size_t subdomains, double max_area) {
  pdd::generate_options g;
  g.criteria = {.min_angle_deg = 20.7, .max_area = max_area};
  g.subdomains = subdomains;
  g.threads = 2;
  return g;
}

/// The message of the meshing_error that f throws; fails the test when it throws none.
template <class F>
std::string error_of(F&& f) {
  try {
    f();
  } catch (const pdd::meshing_error& e) {
    return e.what();
  }
  ADD_FAILURE() << "no pdd::meshing_error";
  return {};
}

} // namespace

TEST(QualityCheck, NamesTheBadTriangleOfAMergedMesh) {
  const pdd::pslg d = long_rectangle();
  const auto g = options(1, 100.0);
  const pdd::generate_result bad = pdd::generate(d, g, lax_mesher{});
  ASSERT_EQ(bad.mesh.triangles.size(), 2u);
  const std::string msg = error_of([&] { pdd::check_quality(bad.mesh, d, g.criteria); });
  EXPECT_NE(msg.find("subdomain 0: quality check failed: triangle 0 ("), std::string::npos) << msg;
  EXPECT_NE(msg.find("smallest angle 5.71059 deg (bound 20.7)"), std::string::npos) << msg;
  EXPECT_NE(msg.find("below the angle bound and not a shielded triangle"), std::string::npos)
      << msg;
  // every vertex of the named triangle is a corner of the rectangle, with all its digits
  int corners = 0;
  for (const char* corner : {"(0, 0)", "(10, 0)", "(10, 1)", "(0, 1)"})
    corners += msg.find(corner) != std::string::npos;
  EXPECT_EQ(corners, 3) << msg;
  // the real kernel passes the same check
  EXPECT_NO_THROW(pdd::check_quality(pdd::generate(d, g).mesh, d, g.criteria));
}

TEST(QualityCheck, CatchesTheAreaBound) {
  const pdd::pslg d = long_rectangle();
  const auto g = options(1, 0.5);
  const pdd::generate_result bad = pdd::generate(d, g, lax_mesher{false, true});
  const std::string msg = error_of([&] { pdd::check_quality(bad.mesh, d, g.criteria); });
  EXPECT_NE(msg.find("above the area bound"), std::string::npos) << msg;
  EXPECT_NO_THROW(pdd::check_quality(pdd::generate(d, g).mesh, d, g.criteria));
}

TEST(QualityCheck, ShieldedTrianglesAreExempt) {
  // A star's 12.5 deg tips are shielded: their triangles keep the input angle and pass.
  const pdd::pslg d = pdd::test::star_polygon(12, 0.3);
  const auto g = options(1, 0.01);
  const pdd::generate_result r = pdd::generate(d, g);
  ASSERT_GT(r.statistics.shielded_triangles, 0u);
  EXPECT_LT(pdd::compute_statistics(r.mesh).min_angle_deg, 20.7);
  EXPECT_NO_THROW(pdd::check_quality(r.mesh, d, g.criteria));
}

TEST(QualityCheck, BadSubdomainMeshIsNeverWrittenNorIndexed) {
  // Decoupled, streamed per subdomain: the check runs before each piece is written, the
  // exception names the subdomain, and the .pvtu index (written last) never appears.
  const pdd::pslg d = long_rectangle();
  const auto g = options(2, 100.0);
  const fs::path dir = pdd::test::temp_path("pieces");
  fs::remove_all(dir);
  pdd::vtu_directory_sink files(dir);
  pdd::quality_check_sink checked(files, d, g.criteria);
  const std::string msg = error_of([&] { pdd::generate(d, g, checked, lax_mesher{}); });
  EXPECT_NE(msg.find("quality check failed: triangle "), std::string::npos) << msg;
  EXPECT_EQ(msg.rfind("subdomain ", 0), 0u) << msg;
  EXPECT_FALSE(fs::exists(files.index_path()));
  for (const auto& piece : files.pieces())
    EXPECT_FALSE(piece.delivered);
  // the real kernel through the same sinks writes the index
  pdd::vtu_directory_sink good_files(dir);
  pdd::quality_check_sink good(good_files, d, g.criteria);
  EXPECT_NO_THROW(pdd::generate(d, g, good));
  EXPECT_TRUE(fs::exists(good_files.index_path()));
}

} // namespace quality_check_test
