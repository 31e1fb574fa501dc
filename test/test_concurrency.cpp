// Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Deformation objects used from several threads at once: each object is
// independent of the others and of anything else the process does, so that
// the same input, options and thread count give the same bits whether the
// objects run one after the other or at the same time, next to a thread
// that factors and solves with the sparse solver directly. Built also with
// ThreadSanitizer (scripts/test.sh), which reports any data race.
#include "test_meshes.h"

#include <CGAL/Spectral_surface_mesh_deformation.h>
#include <CGAL/Spectral_deformation/Sparse_spd_solver_traits.h>

#include <catch2/catch.hpp>

#include <Eigen/Geometry>
#include <Eigen/Sparse>

#include <atomic>
#include <functional>
#include <string>
#include <thread>
#include <vector>

using namespace test_meshes;

namespace {

const double pi = 3.14159265358979323846;

// One deformation job: a mesh, a region (z above `fixed_below`), a handle
// (z above `handle_above`) rotated about the x axis through its centre, two
// drags and a reset in between; the positions after each drag.
struct Job
{
  Soup soup;
  double fixed_below = 0;
  double handle_above = 0;
  std::function<std::vector<Eigen::MatrixXd>(const Job&)> run;
};

Eigen::MatrixXd positions_of(const Surface_mesh& mesh)
{
  Eigen::MatrixXd x(mesh.number_of_vertices(), 3);
  for(auto v : mesh.vertices())
    x.row(v.idx()) << mesh.point(v).x(), mesh.point(v).y(), mesh.point(v).z();
  return x;
}

template <class Deformation>
std::vector<Eigen::MatrixXd> run_job(const Job& job, CGAL::Spectral_constraint_policy policy)
{
  Surface_mesh mesh = to_mesh<Surface_mesh>(job.soup);
  Deformation deformation(mesh);
  std::vector<Surface_mesh::Vertex_index> handle;
  double z_max = -1e300;
  for(auto v : mesh.vertices())
  {
    const double z = mesh.point(v).z();
    z_max = std::max(z_max, z);
    if(z > job.fixed_below)
      deformation.insert_roi_vertex(v);
    if(z > job.handle_above)
      handle.push_back(v);
  }
  deformation.insert_control_vertices(handle.begin(), handle.end());
  if constexpr(Deformation::has_basis)
  {
    deformation.set_number_of_frequencies(40);
    deformation.set_constraint_policy(policy);
  }
  std::vector<Eigen::MatrixXd> results;
  for(double degrees : {30.0, 60.0})
  {
    deformation.reset();
    const Eigen::Quaterniond q(Eigen::AngleAxisd(degrees * pi / 180, Eigen::Vector3d::UnitX()));
    deformation.rotate(handle.begin(), handle.end(), Eigen::Vector3d(0, 0, job.handle_above), q);
    deformation.deform();
    if(!deformation.deform_report().success)
      throw std::runtime_error(deformation.deform_report().message);
    results.push_back(positions_of(mesh));
  }
  return results;
}

std::vector<Job> jobs()
{
  typedef CGAL::Spectral_surface_mesh_deformation<Surface_mesh> Spectral;
  typedef CGAL::Spectral_surface_mesh_deformation<Surface_mesh, CGAL::Default, CGAL::Default,
                                                  CGAL::SPATIAL_DUAL_LAPLACIAN>
      Spatial;
  typedef CGAL::Spectral_surface_mesh_deformation<Surface_mesh, CGAL::Default, CGAL::Default,
                                                  CGAL::SPECTRAL_LINEAR>
      Linear;
  std::vector<Job> list(4);
  list[0].soup = bar(80, 4); // above the dense threshold: block Lanczos
  list[0].fixed_below = 0.5;
  list[0].handle_above = 4.5;
  list[0].run = [](const Job& j) { return run_job<Spectral>(j, CGAL::EXACT_CONSTRAINTS); };
  list[1].soup = icosphere(4);
  list[1].fixed_below = -0.6;
  list[1].handle_above = 0.7;
  list[1].run = [](const Job& j) { return run_job<Spectral>(j, CGAL::SOFT_CONSTRAINTS); };
  list[2].soup = bar(20, 2);
  list[2].fixed_below = 0.3;
  list[2].handle_above = 4.7;
  list[2].run = [](const Job& j) { return run_job<Spatial>(j, CGAL::EXACT_CONSTRAINTS); };
  list[3].soup = icosphere(2);
  list[3].fixed_below = -0.5;
  list[3].handle_above = 0.6;
  list[3].run = [](const Job& j) { return run_job<Linear>(j, CGAL::EXACT_CONSTRAINTS); };
  return list;
}

// Factors and solves a Laplacian-like system with the sparse solver traits
// until `stop` is set; returns whether every solve succeeded.
bool use_sparse_solver(const std::atomic<bool>& stop)
{
  const int n = 2000;
  Eigen::SparseMatrix<double> A(n, n);
  std::vector<Eigen::Triplet<double>> entries;
  for(int i = 0; i < n; ++i)
  {
    entries.emplace_back(i, i, 2.5);
    if(i + 1 < n)
    {
      entries.emplace_back(i, i + 1, -1.0);
      entries.emplace_back(i + 1, i, -1.0);
    }
  }
  A.setFromTriplets(entries.begin(), entries.end());
  const Eigen::MatrixXd b = Eigen::MatrixXd::Ones(n, 3);
  bool ok = true;
  int rounds = 0;
  while(!stop.load() || rounds < 3)
  {
    CGAL::Default_sparse_spd_solver_traits solver;
    Eigen::MatrixXd x;
    ok = ok && solver.factor(A) && solver.solve(b, x) && ((A * x - b).norm() < 1e-8 * b.norm());
    ++rounds;
  }
  return ok;
}

} // namespace

TEST_CASE("concurrency: deformations in parallel threads give the bits of sequential runs",
          "[concurrency]")
{
  const std::vector<Job> list = jobs();
  std::vector<std::vector<Eigen::MatrixXd>> sequential;
  for(const Job& job : list)
    sequential.push_back(job.run(job));

  std::vector<std::vector<Eigen::MatrixXd>> concurrent(list.size());
  std::vector<std::string> failures(list.size());
  std::atomic<bool> stop(false);
  bool sparse_ok = false;
  std::thread sparse_user([&] { sparse_ok = use_sparse_solver(stop); });
  std::vector<std::thread> threads;
  for(std::size_t k = 0; k < list.size(); ++k)
    threads.emplace_back([&, k] {
      try
      {
        concurrent[k] = list[k].run(list[k]);
      }
      catch(const std::exception& e)
      {
        failures[k] = e.what();
      }
    });
  for(std::thread& t : threads)
    t.join();
  stop = true;
  sparse_user.join();

  CHECK(sparse_ok);
  for(std::size_t k = 0; k < list.size(); ++k)
  {
    INFO("job " << k << ": " << failures[k]);
    REQUIRE(failures[k].empty());
    REQUIRE(concurrent[k].size() == sequential[k].size());
    for(std::size_t d = 0; d < sequential[k].size(); ++d)
    {
      CHECK((concurrent[k][d] - sequential[k][d]).cwiseAbs().maxCoeff() == 0.0);
    }
    // The two drags differ: the comparison is not between rest shapes.
    CHECK((sequential[k][1] - sequential[k][0]).cwiseAbs().maxCoeff() > 1e-3);
  }
}
