// Precompiled header shared by the test executables: the heavy third-party headers.
#pragma once
#ifndef PDD_PERMISSIVE // CGAL's GPL packages: the CGAL kernel (Mesh_2)
#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Delaunay_mesher_2.h>
#include <CGAL/Delaunay_triangulation_2.h>
#endif
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <tbb/task_arena.h>
#include <tbb/task_group.h>
