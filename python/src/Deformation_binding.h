// Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// ssmd.Deformation: a CGAL::Surface_mesh built from NumPy arrays, owned
// together with the CGAL::Spectral_surface_mesh_deformation that deforms it.
// The algorithm is a template argument of the C++ class, so the object holds
// one of its three instantiations.

#ifndef SSMD_PYTHON_DEFORMATION_BINDING_H
#define SSMD_PYTHON_DEFORMATION_BINDING_H

#include "Numpy_mesh.h"
#include "Progress_bridge.h"

#include <CGAL/Spectral_surface_mesh_deformation.h>

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <Eigen/Dense>

#include <cstdio>
#include <fstream>
#include <limits>
#include <memory>
#include <mutex>
#include <string>
#include <variant>
#include <vector>

namespace ssmd_python {

namespace py = pybind11;

template <CGAL::Spectral_deformation_algorithm_tag TAG>
using Deformation_of = CGAL::Spectral_surface_mesh_deformation<Mesh, CGAL::Default, CGAL::Default, TAG>;

inline CGAL::Spectral_deformation_algorithm_tag algorithm_from_name(const std::string& name)
{
  if(name == "spectral")
    return CGAL::SPECTRAL_DUAL_LAPLACIAN;
  if(name == "linear")
    return CGAL::SPECTRAL_LINEAR;
  if(name == "spatial")
    return CGAL::SPATIAL_DUAL_LAPLACIAN;
  throw py::value_error("algorithm must be 'spectral', 'linear' or 'spatial', not '" + name + "'");
}

inline CGAL::Spectral_constraint_policy policy_from_name(const std::string& name)
{
  if(name == "exact")
    return CGAL::EXACT_CONSTRAINTS;
  if(name == "soft")
    return CGAL::SOFT_CONSTRAINTS;
  throw py::value_error("policy must be 'exact' or 'soft', not '" + name + "'");
}

// Whether the basis is exact: 'exact' or 'approximate' (the library's default).
inline bool exact_basis_from_name(const std::string& name)
{
  if(name == "approximate")
    return false;
  if(name == "exact")
    return true;
  throw py::value_error("basis must be 'approximate' or 'exact', not '" + name + "'");
}

inline CGAL::Spectral_smooth_energy energy_from_name(const std::string& name)
{
  if(name == "dual_laplacian")
    return CGAL::DUAL_LAPLACIAN_ENERGY;
  if(name == "arap")
    return CGAL::ARAP_ENERGY;
  if(name == "dual_laplacian_and_arap")
    return CGAL::DUAL_LAPLACIAN_AND_ARAP_ENERGY;
  throw py::value_error("energy must be 'dual_laplacian', 'arap' or 'dual_laplacian_and_arap', not '" + name + "'");
}

inline py::dict to_dict(const CGAL::Spectral_preprocess_report& r)
{
  py::dict d;
  d["success"] = r.success;
  d["message"] = r.message;
  d["region_rebuilt"] = r.region_rebuilt;
  d["basis_computed"] = r.basis_computed;
  d["single_precision_basis"] = r.single_precision_basis;
  d["number_of_region_vertices"] = r.number_of_region_vertices;
  d["number_of_frequencies"] = r.number_of_frequencies;
  d["number_of_constrained_vertices"] = r.number_of_constrained_vertices;
  d["region_seconds"] = r.region_seconds;
  d["basis_seconds"] = r.basis_seconds;
  d["factorization_seconds"] = r.factorization_seconds;
  return d;
}

inline py::dict to_dict(const CGAL::Spectral_deformation_report& r)
{
  py::dict d;
  d["success"] = r.success;
  d["message"] = r.message;
  d["iterations"] = r.iterations;
  d["stages"] = r.stages;
  d["volume_preserved"] = r.volume_preserved;
  d["last_step"] = r.last_step;
  d["converged"] = r.converged;
  d["max_control_residual"] = r.max_control_residual;
  d["rms_control_residual"] = r.rms_control_residual;
  d["solve_seconds"] = r.solve_seconds;
  d["detail_transfer_seconds"] = r.detail_transfer_seconds;
  d["total_seconds"] = r.total_seconds;
  return d;
}

inline py::list to_list(const std::vector<double>& values)
{
  py::list list;
  for(double x : values)
    list.append(x);
  return list;
}

inline py::dict to_dict(const CGAL::Spectral_refinement_report& r)
{
  py::dict d;
  d["success"] = r.success;
  d["message"] = r.message;
  d["iterations"] = r.iterations;
  d["energy_before"] = r.energy_before;
  d["energy_after"] = r.energy_after;
  d["converged"] = r.converged;
  d["volume_preserved"] = r.volume_preserved;
  d["energies"] = to_list(r.energies);
  d["seconds_at_iteration"] = to_list(r.seconds_at_iteration);
  d["factorization_seconds"] = r.factorization_seconds;
  d["total_seconds"] = r.total_seconds;
  return d;
}

// What the constructor takes besides the arrays.
struct Deformation_settings
{
  std::string algorithm = "spectral";
  std::size_t frequencies = 100;
  std::string policy = "exact";
  std::string energy = "dual_laplacian_and_arap";
  std::string basis = "approximate";
  double constraint_weight = -1; // negative: the library's default
  long long single_precision_basis_threshold = -1; // negative: the library's default
  long long rotation_patches = -1; // negative: the library's default
  double stage_angle = -1;         // degrees; negative: the library's default
  bool volume_preservation = false;
  std::string basis_cache;       // empty: none
};

class Deformation_session
{
public:
  Deformation_session(const py::handle& vertices, const py::handle& faces, const py::handle& roi,
                      const py::handle& handles, const py::handle& fixed,
                      const Deformation_settings& settings, py::object progress, py::object warn)
    : m_settings(settings)
  {
    fill_mesh(vertices, faces, m_mesh);
    const std::size_t n = m_mesh.number_of_vertices();
    if(handles.is_none())
      throw py::value_error("handles must list the control vertices");
    m_handles = checked_vertex_indices(handles, n, "handles");
    const std::vector<std::size_t> fixed_list =
        fixed.is_none() ? std::vector<std::size_t>() : checked_vertex_indices(fixed, n, "fixed");
    std::vector<char> is_roi(n, roi.is_none() ? 1 : 0);
    if(!roi.is_none())
      for(std::size_t v : checked_vertex_indices(roi, n, "roi"))
        is_roi[v] = 1;
    for(std::size_t v : fixed_list)
    {
      if(!roi.is_none() && is_roi[v])
        throw py::value_error("vertex " + std::to_string(v) +
                              " is both in roi and in fixed; the vertices outside roi are the fixed ones");
      is_roi[v] = 0;
    }
    for(std::size_t v : m_handles)
      if(!is_roi[v])
        throw py::value_error("handle vertex " + std::to_string(v) +
                              " is not in the region of interest (it is fixed)");

    m_is_roi = std::move(is_roi);
    build_deformation();
    if(!settings.basis_cache.empty() && !has_basis())
      throw py::value_error("basis_cache: the 'spatial' algorithm has no basis");
    preprocess_with(progress, warn);
  }

  bool has_basis() const { return m_deformation.index() != 2; }

  std::size_t number_of_vertices() const { return m_mesh.number_of_vertices(); }

  py::array_t<std::int64_t> handles() const
  {
    py::array_t<std::int64_t> result(static_cast<py::ssize_t>(m_handles.size()));
    std::copy(m_handles.begin(), m_handles.end(), result.mutable_data());
    return result;
  }

  py::array_t<std::int64_t> roi()
  {
    std::vector<std::int64_t> indices;
    visit([&](auto& d) {
      for(Vertex_index v : d.roi_vertices())
        indices.push_back(static_cast<std::int64_t>(std::size_t(v)));
    });
    std::sort(indices.begin(), indices.end());
    py::array_t<std::int64_t> result(static_cast<py::ssize_t>(indices.size()));
    std::copy(indices.begin(), indices.end(), result.mutable_data());
    return result;
  }

  py::array_t<double> vertices() const { return positions(m_mesh); }

  py::array_t<double> targets()
  {
    py::array_t<double> result({static_cast<py::ssize_t>(m_handles.size()), py::ssize_t(3)});
    double* out = result.mutable_data();
    visit([&](auto& d) {
      for(std::size_t i = 0; i < m_handles.size(); ++i)
      {
        const Point& p = d.target_position(Vertex_index(static_cast<Mesh::size_type>(m_handles[i])));
        out[3 * i] = p.x();
        out[3 * i + 1] = p.y();
        out[3 * i + 2] = p.z();
      }
    });
    return result;
  }

  // Rows of `points` are the new targets of the handles, in the order of
  // `handles`, or of `subset` (indices into `handles`) when given.
  void set_targets(const py::handle& points, const py::handle& subset)
  {
    const std::vector<std::size_t> which = selected_handles(subset);
    const Double_array p = checked_points(points, "targets");
    if(static_cast<std::size_t>(p.shape(0)) != which.size())
      throw py::value_error("targets has " + std::to_string(p.shape(0)) + " rows for " +
                            std::to_string(which.size()) + " handles");
    std::vector<Point> new_targets;
    for(std::size_t i = 0; i < which.size(); ++i)
      new_targets.emplace_back(p.at(i, 0), p.at(i, 1), p.at(i, 2));
    apply_targets(which, new_targets);
  }

  void translate(const py::handle& vector, const py::handle& subset)
  {
    const std::vector<double> t = checked_vector3(vector, "vector");
    const std::vector<std::size_t> which = selected_handles(subset);
    std::vector<Point> new_targets;
    visit([&](auto& d) {
      for(std::size_t i : which)
      {
        const Point& p = d.target_position(handle_vertex(i));
        new_targets.emplace_back(p.x() + t[0], p.y() + t[1], p.z() + t[2]);
      }
    });
    apply_targets(which, new_targets);
  }

  // `rotation` is a 3 x 3 rotation matrix or a unit quaternion (w, x, y, z);
  // the centre defaults to the centroid of the rotated targets.
  void rotate(const py::handle& rotation, const py::handle& center, const py::handle& subset)
  {
    const Eigen::Matrix3d R = rotation_matrix(rotation);
    const std::vector<std::size_t> which = selected_handles(subset);
    std::vector<Eigen::Vector3d> current;
    visit([&](auto& d) {
      for(std::size_t i : which)
      {
        const Point& p = d.target_position(handle_vertex(i));
        current.emplace_back(p.x(), p.y(), p.z());
      }
    });
    Eigen::Vector3d c = Eigen::Vector3d::Zero();
    if(center.is_none())
    {
      for(const Eigen::Vector3d& p : current)
        c += p;
      if(!current.empty())
        c /= double(current.size());
    }
    else
    {
      const std::vector<double> given = checked_vector3(center, "center");
      c = Eigen::Vector3d(given[0], given[1], given[2]);
    }
    std::vector<Point> new_targets;
    for(const Eigen::Vector3d& p : current)
    {
      const Eigen::Vector3d q = c + R * (p - c);
      new_targets.emplace_back(q[0], q[1], q[2]);
    }
    apply_targets(which, new_targets);
  }

  py::array_t<double> deform(unsigned int iterations, double tolerance)
  {
    if(!(tolerance >= 0))
      throw py::value_error("tolerance must be a non-negative number");
    {
      py::gil_scoped_release release;
      std::lock_guard<std::mutex> lock(m_mutex);
      visit([&](auto& d) { d.deform(iterations, tolerance); });
    }
    const CGAL::Spectral_deformation_report report = deform_report_struct();
    if(!report.success)
    {
      // A failed preprocess() is a problem of the input; anything later is
      // numerical.
      if(report.message.rfind("preprocess() failed", 0) == 0)
        throw py::value_error(report.message);
      throw std::runtime_error("deform() failed: " + report.message);
    }
    return positions(m_mesh);
  }

  // Unlike deform(), a failure is no exception: the library's refine()
  // answers it (a negative or NaN tolerance included) with false and the
  // reason in refine_report, and leaves the positions unchanged.
  bool refine(unsigned int max_iterations, double tolerance)
  {
    bool success = false;
    {
      py::gil_scoped_release release;
      std::lock_guard<std::mutex> lock(m_mutex);
      visit([&](auto& d) { success = d.refine(max_iterations, tolerance); });
    }
    return success;
  }

  void reset()
  {
    std::lock_guard<std::mutex> lock(m_mutex);
    visit([&](auto& d) { d.reset(); });
  }

  py::dict preprocess_report()
  {
    py::dict result;
    visit([&](auto& d) { result = to_dict(d.preprocess_report()); });
    return result;
  }

  py::dict deform_report() { return to_dict(deform_report_struct()); }

  py::dict refine_report()
  {
    py::dict result;
    visit([&](auto& d) { result = to_dict(d.refine_report()); });
    return result;
  }

  void save_basis(const std::string& file)
  {
    require_basis("save_basis");
    py::gil_scoped_release release;
    std::lock_guard<std::mutex> lock(m_mutex);
    write_basis_file(file);
  }

  void load_basis(const std::string& file, py::object progress, py::object warn)
  {
    require_basis("load_basis");
    {
      py::gil_scoped_release release;
      std::lock_guard<std::mutex> lock(m_mutex);
      read_basis_file(file);
    }
    preprocess_with(progress, warn);
  }

private:
  typedef std::variant<std::unique_ptr<Deformation_of<CGAL::SPECTRAL_DUAL_LAPLACIAN>>,
                       std::unique_ptr<Deformation_of<CGAL::SPECTRAL_LINEAR>>,
                       std::unique_ptr<Deformation_of<CGAL::SPATIAL_DUAL_LAPLACIAN>>>
      Any_deformation;

  template <class F>
  void visit(F&& f)
  {
    std::visit([&](auto& d) { f(*d); }, m_deformation);
  }

  void create(CGAL::Spectral_deformation_algorithm_tag algorithm)
  {
    switch(algorithm)
    {
    case CGAL::SPECTRAL_DUAL_LAPLACIAN:
      m_deformation = std::make_unique<Deformation_of<CGAL::SPECTRAL_DUAL_LAPLACIAN>>(m_mesh);
      break;
    case CGAL::SPECTRAL_LINEAR:
      m_deformation = std::make_unique<Deformation_of<CGAL::SPECTRAL_LINEAR>>(m_mesh);
      break;
    case CGAL::SPATIAL_DUAL_LAPLACIAN:
      m_deformation = std::make_unique<Deformation_of<CGAL::SPATIAL_DUAL_LAPLACIAN>>(m_mesh);
      break;
    }
  }

  // A new deformation object for the region and handles, at rest.
  void build_deformation()
  {
    create(algorithm_from_name(m_settings.algorithm));
    const CGAL::Spectral_constraint_policy policy = policy_from_name(m_settings.policy);
    const CGAL::Spectral_smooth_energy energy = energy_from_name(m_settings.energy);
    visit([&](auto& d) {
      if constexpr(std::decay_t<decltype(d)>::has_basis)
      {
        d.set_number_of_frequencies(m_settings.frequencies);
        d.set_constraint_policy(policy);
        d.set_smooth_energy(energy);
        if(m_settings.constraint_weight >= 0)
          d.set_constraint_weight(m_settings.constraint_weight);
        if(m_settings.single_precision_basis_threshold >= 0)
          d.set_single_precision_basis_threshold(
              static_cast<std::size_t>(m_settings.single_precision_basis_threshold));
        if(m_settings.rotation_patches >= 0)
          d.set_rotation_patches(static_cast<std::size_t>(m_settings.rotation_patches));
        if(m_settings.stage_angle >= 0)
          d.set_stage_angle(m_settings.stage_angle);
        d.set_volume_preservation(m_settings.volume_preservation);
      }
      std::vector<Vertex_index> roi_vertices;
      for(std::size_t v = 0; v < m_is_roi.size(); ++v)
        if(m_is_roi[v])
          roi_vertices.push_back(Vertex_index(static_cast<Mesh::size_type>(v)));
      d.insert_roi_vertices(roi_vertices.begin(), roi_vertices.end());
      for(std::size_t v : m_handles)
        d.insert_control_vertex(Vertex_index(static_cast<Mesh::size_type>(v)));
    });
  }

  Vertex_index handle_vertex(std::size_t i) const
  {
    return Vertex_index(static_cast<Mesh::size_type>(m_handles[i]));
  }

  std::vector<std::size_t> selected_handles(const py::handle& subset) const
  {
    if(subset.is_none())
    {
      std::vector<std::size_t> all(m_handles.size());
      for(std::size_t i = 0; i < all.size(); ++i)
        all[i] = i;
      return all;
    }
    return checked_vertex_indices(subset, m_handles.size(), "which (indices into handles)");
  }

  // All targets are checked before the first is set: a failure changes none.
  void apply_targets(const std::vector<std::size_t>& which, const std::vector<Point>& new_targets)
  {
    for(const Point& p : new_targets)
      if(!std::isfinite(p.x()) || !std::isfinite(p.y()) || !std::isfinite(p.z()))
        throw py::value_error("a new target is not finite");
    std::lock_guard<std::mutex> lock(m_mutex);
    visit([&](auto& d) {
      for(std::size_t k = 0; k < which.size(); ++k)
        d.set_target_position(handle_vertex(which[k]), new_targets[k]);
    });
  }

  static Eigen::Matrix3d rotation_matrix(const py::handle& rotation)
  {
    const Double_array a = as_double_array(rotation, "rotation");
    const double* r = a.data();
    for(py::ssize_t i = 0; i < a.size(); ++i)
      if(!std::isfinite(r[i]))
        throw py::value_error("rotation must be finite");
    if(a.ndim() == 1 && a.shape(0) == 4)
    {
      Eigen::Quaterniond q(r[0], r[1], r[2], r[3]);
      if(std::abs(q.norm() - 1) > 1e-6)
        throw py::value_error("rotation: the quaternion (w, x, y, z) must have norm 1");
      return q.normalized().toRotationMatrix();
    }
    if(a.ndim() == 2 && a.shape(0) == 3 && a.shape(1) == 3)
    {
      Eigen::Matrix3d R;
      for(int i = 0; i < 3; ++i)
        for(int j = 0; j < 3; ++j)
          R(i, j) = r[3 * i + j];
      if(!(R.transpose() * R).isApprox(Eigen::Matrix3d::Identity(), 1e-6) || R.determinant() < 0)
        throw py::value_error("rotation: the 3 x 3 matrix is not a rotation (orthonormal, determinant 1)");
      return R;
    }
    throw py::value_error("rotation must be a 3 x 3 matrix or a quaternion (w, x, y, z)");
  }

  CGAL::Spectral_deformation_report deform_report_struct()
  {
    CGAL::Spectral_deformation_report report;
    visit([&](auto& d) { report = d.deform_report(); });
    return report;
  }

  void require_basis(const char* what) const
  {
    if(!has_basis())
      throw py::value_error(std::string(what) + ": the 'spatial' algorithm has no basis");
  }

  // Writes through a temporary file, so that an interrupted write never
  // leaves a truncated cache.
  void write_basis_file(const std::string& file)
  {
    const std::string temporary = file + ".partial";
    {
      std::ofstream out(temporary, std::ios::binary);
      if(!out)
        throw CGAL::Spectral_deformation_error(CGAL::Spectral_deformation_error::IO_ERROR,
                                               "cannot write " + temporary);
      visit([&](auto& d) {
        if constexpr(std::decay_t<decltype(d)>::has_basis)
          d.save_basis(out);
      });
      out.close();
      if(!out)
        throw CGAL::Spectral_deformation_error(CGAL::Spectral_deformation_error::IO_ERROR,
                                               "cannot write " + temporary);
    }
    if(std::rename(temporary.c_str(), file.c_str()) != 0)
    {
      std::remove(temporary.c_str());
      throw CGAL::Spectral_deformation_error(CGAL::Spectral_deformation_error::IO_ERROR,
                                             "cannot rename " + temporary + " to " + file);
    }
  }

  void read_basis_file(const std::string& file)
  {
    std::ifstream in(file, std::ios::binary);
    if(!in)
      throw CGAL::Spectral_deformation_error(CGAL::Spectral_deformation_error::IO_ERROR,
                                             "cannot open " + file);
    visit([&](auto& d) {
      if constexpr(std::decay_t<decltype(d)>::has_basis)
        d.load_basis(in);
    });
  }

  // preprocess() with the progress reported to `progress`, through the basis
  // cache when there is one: a cache that cannot be used (missing, corrupted,
  // of another mesh or another number of frequencies) is recomputed and
  // rewritten, with a warning through `warn` except when it is missing.
  void preprocess_with(py::object progress, py::object warn)
  {
    const std::string& cache = m_settings.basis_cache;
    bool loaded = false;
    if(!cache.empty() && std::ifstream(cache).good())
    {
      try
      {
        py::gil_scoped_release release;
        std::lock_guard<std::mutex> lock(m_mutex);
        read_basis_file(cache);
        loaded = true;
      }
      catch(const CGAL::Spectral_deformation_error& e)
      {
        warn(std::string("the basis cache ") + cache + " cannot be used (" + e.what() +
             "): the basis is recomputed");
      }
    }
    run_preprocess(progress);
    if(loaded)
    {
      const CGAL::Spectral_preprocess_report report = preprocess_report_struct();
      if(report.number_of_frequencies != std::min(m_settings.frequencies, report.number_of_region_vertices))
      {
        warn("the basis cache " + cache + " holds " + std::to_string(report.number_of_frequencies) +
             " frequencies, not " + std::to_string(m_settings.frequencies) + ": the basis is recomputed");
        build_deformation();
        run_preprocess(progress);
      }
    }
    if(!cache.empty() && preprocess_report_struct().basis_computed)
    {
      try
      {
        py::gil_scoped_release release;
        std::lock_guard<std::mutex> lock(m_mutex);
        write_basis_file(cache);
      }
      catch(const CGAL::Spectral_deformation_error& e)
      {
        warn(std::string("the basis cache cannot be written: ") + e.what());
      }
    }
  }

  void run_preprocess(py::object progress)
  {
    Progress_bridge bridge(progress);
    bool success = false;
    {
      py::gil_scoped_release release;
      std::lock_guard<std::mutex> lock(m_mutex);
      visit([&](auto& d) {
        typedef std::decay_t<decltype(d)> Deformation;
        if constexpr(Deformation::has_basis)
          d.set_eigensolver_traits(basis_traits(bridge.traits<typename Deformation::Eigensolver_traits>()));
        success = d.preprocess();
        // The traits refer to the bridge, which dies with this call.
        if constexpr(Deformation::has_basis)
          d.set_eigensolver_traits(basis_traits(typename Deformation::Eigensolver_traits()));
      });
    }
    bridge.rethrow_if_failed();
    if(!success)
      throw py::value_error(preprocess_report_struct().message);
  }

  // The eigensolver traits of the setting `basis`: the approximate basis
  // solves exactly at every size with an infinite exact threshold.
  template <class Traits>
  Traits basis_traits(Traits traits) const
  {
    if(exact_basis_from_name(m_settings.basis))
      traits.set_exact_threshold(std::numeric_limits<double>::infinity());
    return traits;
  }

  CGAL::Spectral_preprocess_report preprocess_report_struct()
  {
    CGAL::Spectral_preprocess_report report;
    visit([&](auto& d) { report = d.preprocess_report(); });
    return report;
  }

  Deformation_settings m_settings;
  Mesh m_mesh;
  std::vector<std::size_t> m_handles;
  std::vector<char> m_is_roi;
  Any_deformation m_deformation;
  // Calls from several Python threads on one object are serialized: the GIL
  // is released during the long ones.
  std::mutex m_mutex;
};

} // namespace ssmd_python

#endif // SSMD_PYTHON_DEFORMATION_BINDING_H
