// 20_custom_partitioner: plug a graph partitioner of your own into pdd. Any type with
// `std::vector<std::uint8_t> bisect(const partition_graph&, const bisection_options&) const`
// models pdd::GraphPartitioner; pdd::connected_bisection then guarantees two connected parts.
#include <pdd/concepts/graph_partitioner.hpp>
#include <pdd/partition/bisection_metrics.hpp>
#include <pdd/partition/connectivity.hpp>

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <numeric>
#include <vector>

// Coordinate bisection: orders the vertices by x and gives part 0 the left share of the weight
// (bisection_options::target_fraction: a half unless MADD asks for uneven shares).
struct coordinate_partitioner {
  std::vector<double> x; // one coordinate per vertex

  std::vector<std::uint8_t> bisect(const pdd::partition_graph& g,
                                   const pdd::bisection_options& o) const {
    std::vector<std::size_t> order(boost::num_vertices(g));
    std::iota(order.begin(), order.end(), std::size_t{0});
    std::stable_sort(order.begin(), order.end(),
                     [&](std::size_t a, std::size_t b) { return x[a] < x[b]; });
    double total = 0.0, left = 0.0;
    for (std::size_t v : order)
      total += g[v].weight;
    std::vector<std::uint8_t> part(order.size(), 1);
    for (std::size_t i = 0; i + 1 < order.size() && left < o.target_fraction * total; ++i) {
      part[order[i]] = 0;
      left += g[order[i]].weight;
    }
    return part;
  }
};
static_assert(pdd::GraphPartitioner<coordinate_partitioner>);

int main() {
  // A C-shaped region of unit cells (8 x 6, the middle of the right side cut out): vertices are
  // cells weighted by area, edges are shared cell sides weighted by length, as in MADD.
  const int w = 8, h = 6;
  auto inside = [](int i, int j) { return !(i >= 3 && j >= 2 && j <= 3); };
  std::vector<int> id(w * h, -1);
  pdd::partition_graph g;
  coordinate_partitioner by_x;
  for (int j = 0; j < h; ++j)
    for (int i = 0; i < w; ++i)
      if (inside(i, j)) {
        id[j * w + i] = static_cast<int>(boost::add_vertex(g));
        g[id[j * w + i]].weight = 1.0;
        by_x.x.push_back(i + 0.5);
      }
  for (int j = 0; j < h; ++j)
    for (int i = 0; i < w; ++i) {
      if (id[j * w + i] < 0) continue;
      if (i + 1 < w && id[j * w + i + 1] >= 0)
        boost::add_edge(id[j * w + i], id[j * w + i + 1], pdd::partition_edge{1.0}, g);
      if (j + 1 < h && id[(j + 1) * w + i] >= 0)
        boost::add_edge(id[j * w + i], id[(j + 1) * w + i], pdd::partition_edge{1.0}, g);
    }

  const pdd::bisection_options options{.max_part_fraction = 0.6};
  const auto raw = by_x.bisect(g, options); // its right half is the two arms of the C
  const auto part = pdd::connected_bisection(g, by_x, options);
  const auto weights = pdd::part_weights(g, part);
  std::printf("coordinate split: cut %.0f (right part disconnected)\n", pdd::cut_weight(g, raw));
  std::printf("connected_bisection: cut %.0f, part areas %.0f and %.0f\n", pdd::cut_weight(g, part),
              weights[0], weights[1]);
  return weights[0] > 0 && weights[1] > 0 ? 0 : 1;
}
