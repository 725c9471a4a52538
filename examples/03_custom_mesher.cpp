// Example 3: a custom DelaunayMesher that wraps the default kernel and counts its calls.
// Any type with `mesh(pslg, mesh_criteria, SizingField) -> mesher_result` and the semantics in
// <pdd/concepts/delaunay_mesher.hpp> plugs into pdd's pipelines in place of the default kernel.
#include <pdd/concepts/delaunay_mesher.hpp>
#include <pdd/geometry/model_domains.hpp>
#include <pdd/kernels/default_mesher.hpp>
#include <pdd/sizing/uniform.hpp>

#include <atomic>
#include <cstdio>
#include <memory>

class counting_mesher {
public:
  template <pdd::SizingField S>
  pdd::mesher_result mesh(const pdd::pslg& d, const pdd::mesh_criteria& c, const S& s) const {
    calls_->fetch_add(1, std::memory_order_relaxed); // thread-safe: kernels run concurrently
    return inner_.mesh(d, c, s);
  }
  long calls() const { return calls_->load(); }

private:
  pdd::default_mesher inner_;
  std::shared_ptr<std::atomic<long>> calls_ = std::make_shared<std::atomic<long>>(0);
};
static_assert(pdd::DelaunayMesher<counting_mesher>);

int main() {
  const counting_mesher mesher;
  const pdd::pslg key = pdd::key_domain();
  for (double area : {0.05, 0.01, 0.002}) {
    const auto r =
        mesher.mesh(key, pdd::mesh_criteria{.max_area = area}, pdd::uniform_sizing{area});
    std::printf("max area %-6g -> %zu triangles\n", area, r.mesh.num_triangles());
  }
  std::printf("the kernel was called %ld times\n", mesher.calls());
  return mesher.calls() == 3 ? 0 : 1;
}
