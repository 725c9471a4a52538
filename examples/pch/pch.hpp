// Precompiled header shared by the drivers, examples and benchmarks: the heavy third-party
// headers every pdd program includes through pdd's headers.
#pragma once
#ifndef PDD_PERMISSIVE // CGAL's GPL packages: the CGAL kernel (Mesh_2)
#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Delaunay_mesher_2.h>
#include <CGAL/Delaunay_triangulation_2.h>
#endif
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <boost/graph/adjacency_list.hpp>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>
