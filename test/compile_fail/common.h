// Sources that must NOT compile: each misuse of the API stops with the package's own message
// (test/CMakeLists.txt builds each and expects that message).
#include <CGAL_pmsum/point_minkowski_sum.h>

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <iterator>
#include <vector>

using IK = CGAL::Exact_predicates_inexact_constructions_kernel;
using EK = CGAL::Exact_predicates_exact_constructions_kernel;
using Mesh = CGAL::Surface_mesh<IK::Point_3>;
