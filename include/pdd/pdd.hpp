/// \file pdd.hpp
/// Umbrella header: every public pdd header (not detail/), grouped by the level of its module.
/// Include single headers to compile faster. Not included here: pdd/mpi/ (MPI programs only;
/// target pdd::mpi), pdd/triangle/ (Triangle's interface, over generate) and
/// pdd/sizing/expression.hpp (target pdd::expression).
///
/// Layering: a module includes only modules on lower levels and only its own detail/. The
/// levels are in one table, in include/pdd/README.md; tests/layering/check_layering.py reads
/// it and checks every `#include`.
#pragma once

// level 0: core, errors
#include <pdd/core/bbox.hpp>
#include <pdd/core/index.hpp>
#include <pdd/core/kernel.hpp>
#include <pdd/core/mesh_criteria.hpp>
#include <pdd/core/point.hpp>
#include <pdd/core/pslg.hpp>
#include <pdd/core/segment_markers.hpp>
#include <pdd/core/triangle_measures.hpp>
#include <pdd/core/triangle_mesh.hpp>
#include <pdd/errors.hpp>

// level 1: triangulation
#include <pdd/triangulation/constrained_delaunay_2.hpp>

// level 2: concepts, geometry
#include <pdd/concepts/delaunay_mesher.hpp>
#include <pdd/concepts/executor.hpp>
#include <pdd/concepts/graph_partitioner.hpp>
#include <pdd/concepts/mesh_sink.hpp>
#include <pdd/concepts/sizing_field.hpp>
#include <pdd/geometry/box_pairs.hpp>
#include <pdd/geometry/domain_angles.hpp>
#include <pdd/geometry/domain_faces.hpp>
#include <pdd/geometry/feature_gap.hpp>
#include <pdd/geometry/lfs.hpp>
#include <pdd/geometry/loop_structure.hpp>
#include <pdd/geometry/loops.hpp>
#include <pdd/geometry/model_domains.hpp>
#include <pdd/geometry/properties.hpp>
#include <pdd/geometry/validate.hpp>

// level 3: sizing, partition, kernels, parallel
#ifndef PDD_PERMISSIVE // CGAL's Mesh_2 (GPL)
#include <pdd/kernels/cgal/criteria.hpp>
#include <pdd/kernels/cgal/mesher.hpp>
#endif
#include <pdd/kernels/default_mesher.hpp>
#include <pdd/parallel/parallel_for.hpp>
#include <pdd/parallel/schedule_order.hpp>
#include <pdd/parallel/sequential_executor.hpp>
#include <pdd/parallel/tbb_executor.hpp>
#include <pdd/partition/bisection_metrics.hpp>
#include <pdd/partition/boost_partitioner.hpp>
#include <pdd/partition/connectivity.hpp>
#include <pdd/partition/default_partitioner.hpp>
#include <pdd/partition/metis.hpp>
#include <pdd/sizing/analytic.hpp>
#include <pdd/sizing/any_sizing.hpp>
#include <pdd/sizing/background_mesh.hpp>
#include <pdd/sizing/geometric_bound.hpp>
#include <pdd/sizing/grid.hpp>
#include <pdd/sizing/inverse_area_integral.hpp>
#include <pdd/sizing/mesh_size_estimate.hpp>
#include <pdd/sizing/min_sizing.hpp>
#include <pdd/sizing/piecewise_scaled.hpp>
#include <pdd/sizing/regional.hpp>
#include <pdd/sizing/sizing_range.hpp>
#include <pdd/sizing/uniform.hpp>
// pdd/sizing/expression.hpp (muParser) is not included here: it needs the pdd::expression target

// level 4: madd
#include <pdd/core/decomposition.hpp>
#include <pdd/madd/decompose.hpp>
#include <pdd/madd/decomposition_measures.hpp>
#include <pdd/madd/decomposition_statistics.hpp>
#include <pdd/madd/face_decoupling.hpp>
#include <pdd/madd/madd_options.hpp>
#include <pdd/madd/madd_start.hpp>
#include <pdd/madd/subdomain_pslg.hpp>
#include <pdd/madd/validate_decomposition.hpp>

// level 5: shielding
#include <pdd/shielding/apply_shields.hpp>
#include <pdd/shielding/graded_shields.hpp>
#include <pdd/shielding/shield.hpp>
#include <pdd/shielding/shield_decomposition.hpp>
#include <pdd/shielding/shield_statistics.hpp>
#include <pdd/shielding/shield_triangle.hpp>
#include <pdd/shielding/shielded_domain.hpp>
#include <pdd/shielding/subdomain_shields.hpp>

// level 6: decoupling
#include <pdd/decoupling/decouple.hpp>
#include <pdd/decoupling/decoupled_decomposition.hpp>
#include <pdd/decoupling/decoupling_parameter.hpp>
#include <pdd/decoupling/geometric_decompose.hpp>
#include <pdd/decoupling/geometric_sizing.hpp>
#include <pdd/decoupling/graded_decouple.hpp>
#include <pdd/decoupling/interface_split.hpp>
#include <pdd/decoupling/invariance.hpp>

// level 7: io, meshing
#include <pdd/io/angle_histogram.hpp>
#include <pdd/io/area_grid.hpp>
#include <pdd/io/atomic_file.hpp>
#include <pdd/io/background_mesh.hpp>
#include <pdd/io/decomposition_io.hpp>
#include <pdd/io/msh.hpp>
#include <pdd/io/poly.hpp>
#include <pdd/io/svg.hpp>
#include <pdd/io/svg_options.hpp>
#include <pdd/io/triangle_files.hpp>
#include <pdd/io/vtu.hpp>
#include <pdd/io/vtu_read.hpp>
#include <pdd/io/write_mesh.hpp>
#include <pdd/meshing/mesh_subdomain.hpp>
#include <pdd/meshing/mesh_subdomains.hpp>

// level 8: mesh
#include <pdd/mesh/cluster_exempt.hpp>
#include <pdd/mesh/merge.hpp>
#include <pdd/mesh/mesh_statistics.hpp>
#include <pdd/mesh/quality.hpp>
#include <pdd/mesh/sinks.hpp>
#include <pdd/mesh/statistics_sink.hpp>
#include <pdd/mesh/verification_report.hpp>
#include <pdd/mesh/verify.hpp>
#include <pdd/mesh/verify_pieces.hpp>
#include <pdd/mesh/verifying_sink.hpp>

// level 9: pipeline
#include <pdd/pipeline.hpp>
#include <pdd/pipeline/system.hpp>

// level 10: generate
#include <pdd/generate.hpp>
