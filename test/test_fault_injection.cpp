// Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Allocation failures at every allocation of preprocess() and deform(): the
// k-th allocation made inside the two calls fails (malloc returns null, so
// operator new, Eigen and CHOLMOD all see it), for k = 1, 2, ... until a run
// makes fewer than k allocations. Each failure must give a clear report, leave
// the mesh and the targets as they were, and leave the object usable: the same
// calls without a failure then give the result of a run that never failed.
// (Not built with the sanitizers, which replace malloc themselves, and
// without OpenMP in the package: see test/CMakeLists.txt.)
#include "test_meshes.h"

#include <CGAL/Spectral_surface_mesh_deformation.h>
#include <CGAL/Spectral_deformation/Block_lanczos_eigensolver_traits.h>

#include <catch2/catch.hpp>

#include <Eigen/Geometry>

#include <dlfcn.h>
#include <execinfo.h>

#include <atomic>
#include <cerrno>
#include <cstdlib>
#include <cstdio>
#include <cstring>
#include <string>
#include <type_traits>
#include <vector>

extern "C" void* __libc_malloc(std::size_t);
extern "C" void* __libc_calloc(std::size_t, std::size_t);
extern "C" void* __libc_realloc(void*, std::size_t);
extern "C" void* __libc_memalign(std::size_t, std::size_t);

namespace {

// Allocations left before the one that fails; negative: none fails.
std::atomic<long> allocations_before_failure(-1);

// OpenMP's runtime ends the process when one of its allocations fails
// (CHOLMOD runs OpenMP loops of its own): those are not counted.
bool called_from_openmp_runtime(void* caller)
{
  Dl_info info;
  return dladdr(caller, &info) != 0 && info.dli_fname != nullptr &&
         std::strstr(info.dli_fname, "libgomp") != nullptr;
}

bool allocation_fails(void* caller)
{
  long left = allocations_before_failure.load(std::memory_order_relaxed);
  if(left < 0 || called_from_openmp_runtime(caller))
    return false;
  while(left >= 0)
    if(allocations_before_failure.compare_exchange_weak(left, left - 1))
    {
      if(left == 0 && std::getenv("SSMD_FAULT_TRACE") != nullptr)
      {
        void* frames[24];
        backtrace_symbols_fd(frames, backtrace(frames, 24), 2);
      }
      return left == 0;
    }
  return false;
}

} // namespace

#define SSMD_ALLOCATION_FAILS allocation_fails(__builtin_return_address(0))

extern "C" void* malloc(std::size_t size) { return SSMD_ALLOCATION_FAILS ? nullptr : __libc_malloc(size); }
extern "C" void* calloc(std::size_t count, std::size_t size)
{
  return SSMD_ALLOCATION_FAILS ? nullptr : __libc_calloc(count, size);
}
extern "C" void* realloc(void* pointer, std::size_t size)
{
  return SSMD_ALLOCATION_FAILS ? nullptr : __libc_realloc(pointer, size);
}
extern "C" void* memalign(std::size_t alignment, std::size_t size)
{
  return SSMD_ALLOCATION_FAILS ? nullptr : __libc_memalign(alignment, size);
}
extern "C" void* aligned_alloc(std::size_t alignment, std::size_t size)
{
  return SSMD_ALLOCATION_FAILS ? nullptr : __libc_memalign(alignment, size);
}
extern "C" int posix_memalign(void** pointer, std::size_t alignment, std::size_t size)
{
  if(SSMD_ALLOCATION_FAILS)
    return ENOMEM;
  void* p = __libc_memalign(alignment, size);
  if(p == nullptr)
    return ENOMEM;
  *pointer = p;
  return 0;
}

using namespace test_meshes;

namespace {

const double pi = 3.14159265358979323846;

Eigen::MatrixXd positions_of(const Surface_mesh& mesh)
{
  Eigen::MatrixXd x(mesh.number_of_vertices(), 3);
  for(auto v : mesh.vertices())
    x.row(v.idx()) << mesh.point(v).x(), mesh.point(v).y(), mesh.point(v).z();
  return x;
}

// A small bent bar: the region above z = 0.5, the top ring rotated by 60
// degrees; the block Lanczos eigensolver (dense threshold 0) or the
// approximate basis (exact threshold 0) is forced so that its allocations
// are exercised too.
template <class Deformation>
struct Bent_bar
{
  Surface_mesh mesh = to_mesh<Surface_mesh>(bar(12, 2));
  Deformation deformation{mesh};
  std::vector<Surface_mesh::Vertex_index> handle;

  explicit Bent_bar(CGAL::Spectral_constraint_policy policy)
  {
    for(auto v : mesh.vertices())
    {
      if(mesh.point(v).z() > 0.5)
        deformation.insert_roi_vertex(v);
      if(mesh.point(v).z() > 4.6)
        handle.push_back(v);
    }
    deformation.insert_control_vertices(handle.begin(), handle.end());
    if constexpr(Deformation::has_basis)
    {
      deformation.set_number_of_frequencies(16);
      deformation.set_constraint_policy(policy);
      typedef typename Deformation::Eigensolver_traits Eigensolver_traits;
      if constexpr(std::is_same_v<Eigensolver_traits, CGAL::Block_lanczos_eigensolver_traits<>>)
        deformation.set_eigensolver_traits(Eigensolver_traits(1e-6, 0, 0, 0));
      else
      {
        Eigensolver_traits approximate; // 36 functions for the 16 frequencies
        approximate.set_number_of_samples(12);
        approximate.set_exact_threshold(0);
        deformation.set_eigensolver_traits(approximate);
      }
    }
    const Eigen::Quaterniond q(Eigen::AngleAxisd(pi / 3, Eigen::Vector3d::UnitX()));
    deformation.rotate(handle.begin(), handle.end(), Eigen::Vector3d(0, 0, 5), q);
  }

  // preprocess() and deform(), the k-th allocation failing (k = 0: none).
  // Returns whether the k-th allocation happened.
  bool run(long k)
  {
    allocations_before_failure = k - 1;
    deformation.preprocess();
    deformation.deform();
    const bool failed = (k > 0 && allocations_before_failure.load() < 0);
    allocations_before_failure = -1;
    return failed;
  }

  std::vector<Eigen::Vector3d> targets()
  {
    std::vector<Eigen::Vector3d> t;
    for(auto v : handle)
    {
      const auto& p = deformation.target_position(v);
      t.emplace_back(p.x(), p.y(), p.z());
    }
    return t;
  }
};

template <class Deformation>
void inject_failures(CGAL::Spectral_constraint_policy policy)
{
  Bent_bar<Deformation> reference(policy);
  REQUIRE_FALSE(reference.run(0));
  REQUIRE(reference.deformation.deform_report().success);
  const Eigen::MatrixXd expected = positions_of(reference.mesh);

  long k = 1;
  std::size_t reported = 0;
  for(;; ++k)
  {
    Bent_bar<Deformation> bar(policy);
    const Eigen::MatrixXd rest = positions_of(bar.mesh);
    const std::vector<Eigen::Vector3d> targets = bar.targets();
    if(std::getenv("SSMD_FAULT_TRACE") != nullptr) // the allocation that fails, to replay a crash
      std::fprintf(stderr, "allocation %ld\n", k);
    const bool failed = bar.run(k);
    if(!failed)
      break; // fewer than k allocations: every one has failed once
    const Eigen::MatrixXd after = positions_of(bar.mesh);
    const std::string message = bar.deformation.deform_report().message;
    INFO("allocation " << k << ": " << message);
    CHECK(bar.targets() == targets);
    if(bar.deformation.deform_report().success)
    {
      // The failure was absorbed (deform() preprocesses again after a failed
      // preprocess(), the eigensolver has a fallback): the result is right.
      CHECK((after - expected).cwiseAbs().maxCoeff() < 1e-6);
      continue;
    }
    ++reported;
    CHECK_FALSE(message.empty());
    CHECK(after == rest);
    // Usable afterwards: the same calls without a failure give the result.
    bar.run(0);
    REQUIRE(bar.deformation.deform_report().success);
    CHECK((positions_of(bar.mesh) - expected).cwiseAbs().maxCoeff() < 1e-6);
  }
  INFO(k - 1 << " allocations, " << reported << " failures reported");
  CHECK(k > 20);
  CHECK(reported > 0);
}

} // namespace

TEST_CASE("fault injection: every allocation of preprocess() and deform() may fail", "[robustness][memory]")
{
  typedef CGAL::Spectral_surface_mesh_deformation<Surface_mesh, CGAL::Default, CGAL::Default,
                                                  CGAL::SPECTRAL_DUAL_LAPLACIAN,
                                                  CGAL::Block_lanczos_eigensolver_traits<>>
      Spectral;
  typedef CGAL::Spectral_surface_mesh_deformation<Surface_mesh> Spectral_approximate_basis;
  typedef CGAL::Spectral_surface_mesh_deformation<Surface_mesh, CGAL::Default, CGAL::Default,
                                                  CGAL::SPATIAL_DUAL_LAPLACIAN>
      Spatial;
  SECTION("spectral, exact constraints") { inject_failures<Spectral>(CGAL::EXACT_CONSTRAINTS); }
  SECTION("spectral, soft constraints") { inject_failures<Spectral>(CGAL::SOFT_CONSTRAINTS); }
  SECTION("spectral, approximate basis") { inject_failures<Spectral_approximate_basis>(CGAL::EXACT_CONSTRAINTS); }
  SECTION("spatial") { inject_failures<Spatial>(CGAL::EXACT_CONSTRAINTS); }
}
