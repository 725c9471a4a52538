/// \file generate_entry.hpp
/// What pdd::generate (generate.hpp) returns and the two functions it calls, declared: their
/// definitions are in pipeline/generate_templates.hpp, which libpdd compiles for the built-in
/// kernels with the default partitioner and the TBB executor. A program that calls
/// pdd::generate with a kernel, partitioner or executor of its own includes that header.
#pragma once

#include <pdd/concepts/delaunay_mesher.hpp>
#include <pdd/concepts/executor.hpp>
#include <pdd/concepts/graph_partitioner.hpp>
#include <pdd/core/pslg.hpp>
#include <pdd/core/triangle_mesh.hpp>
#include <pdd/mesh/mesh_sink_ref.hpp>
#include <pdd/pipeline/options.hpp>
#include <pdd/pipeline/statistics.hpp>

namespace pdd {

/// The merged mesh and what it took.
struct generate_result {
  /// One conforming Delaunay mesh of the domain; triangle markers are subdomain ids (0 when
  /// N == 1); segments are the mesh edges on input segments with their markers.
  triangle_mesh mesh;
  /// What the run took: subdomain and triangle counts, times per phase, the decoupling's
  /// conditions (see generate_statistics).
  generate_statistics statistics;
};

namespace detail {
/// pdd::generate into one merged mesh, on options.threads threads.
template <DelaunayMesher M, GraphPartitioner P, Executor E>
generate_result generate_merged(const pslg& domain, const generate_options& options,
                                const M& mesher, const P& partitioner);

/// pdd::generate into the sink `sink` refers to, on options.threads threads.
template <DelaunayMesher M, GraphPartitioner P, Executor E>
generate_statistics generate_into(const pslg& domain, const generate_options& options,
                                  mesh_sink_ref sink, const M& mesher, const P& partitioner);
} // namespace detail

} // namespace pdd
