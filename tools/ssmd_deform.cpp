// Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// ssmd_deform: deforms a triangle mesh given constraints in a .sel/.def pair
// or in a plain-text constraint file, with a cached manifold harmonics basis.
// `ssmd_deform --help` and doc/command_line_tool.md describe the options and
// the formats.

#include "ssmd_deform/Basis_progress_bar.h"
#include "ssmd_deform/Command_line_options.h"
#include "ssmd_deform/Deformation_constraints.h"
#include "ssmd_deform/Rendering.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Spectral_deformation/Partition_of_unity_eigensolver_traits.h>
#include <CGAL/Spectral_deformation/version.h>
#include <CGAL/Spectral_surface_mesh_deformation.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/boost/graph/helpers.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <chrono>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <memory>
#include <new>
#include <sstream>
#include <string>
#include <type_traits>
#include <vector>

#include <unistd.h>

namespace {

typedef CGAL::Exact_predicates_inexact_constructions_kernel Kernel;
typedef Kernel::Point_3 Point;
typedef CGAL::Surface_mesh<Point> Mesh;
typedef Mesh::Vertex_index Vertex_index;
// The eigensolver of --basis exact.
typedef CGAL::Block_lanczos_eigensolver_traits<> Eigensolver_traits;
// The eigensolver of --basis approximate, the class's default.
typedef CGAL::Partition_of_unity_eigensolver_traits<> Approximate_eigensolver_traits;
typedef Deformation_tool::Basis_progress_bar<Eigensolver_traits::Progress> Progress_bar;

const char* const program_name = "ssmd_deform";
const char* const program_version = CGAL_SSMD_VERSION_STR;

/// A failure of the run (exit status 1); the message says what and where.
class Tool_error : public std::runtime_error
{
public:
  explicit Tool_error(const std::string& what) : std::runtime_error(what) {}
};

typedef std::chrono::steady_clock Clock;

double seconds_since(Clock::time_point start)
{
  return std::chrono::duration<double>(Clock::now() - start).count();
}

std::string lowercase_extension(const std::filesystem::path& file)
{
  std::string extension = file.extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return extension;
}

// The formats CGAL::IO::write_polygon_mesh writes without optional libraries.
bool is_writable_format(const std::string& extension)
{
  return extension == ".off" || extension == ".obj" || extension == ".ply" ||
         extension == ".stl" || extension == ".ts";
}

std::string default_output_file(const std::string& mesh_file)
{
  const std::filesystem::path mesh(mesh_file);
  const std::string extension = is_writable_format(lowercase_extension(mesh))
                                    ? mesh.extension().string()
                                    : std::string(".off");
  return (mesh.parent_path() / (mesh.stem().string() + "_deformed" + extension)).string();
}

// Writes `mesh` to `file` through a temporary file in the same directory,
// renamed at the end, so that `file` is either complete or untouched.
void write_mesh_atomically(const Mesh& mesh, const std::string& file)
{
  const std::filesystem::path target(file);
  const std::filesystem::path temporary =
      target.parent_path() / ("." + target.stem().string() + ".partial-" +
                              std::to_string(::getpid()) + target.extension().string());
  bool written = false;
  try
  {
    written = CGAL::IO::write_polygon_mesh(temporary.string(), mesh,
                                           CGAL::parameters::stream_precision(17));
  }
  catch(const std::exception&)
  {
    written = false;
  }
  std::error_code error;
  if(written)
    std::filesystem::rename(temporary, target, error);
  if(!written || error)
  {
    std::filesystem::remove(temporary, error);
    throw Tool_error("cannot write the result to " + file);
  }
}

// Writes the basis cache through a temporary file (a run interrupted while
// writing must not leave a truncated cache). Returns an empty string on
// success, the reason otherwise.
template <class Deformation>
std::string save_basis_cache(const Deformation& deformation, const std::string& file)
{
  const std::string temporary = file + ".partial-" + std::to_string(::getpid());
  try
  {
    {
      errno = 0;
      std::ofstream out(temporary, std::ios::binary);
      if(!out)
        return errno != 0 ? std::strerror(errno) : "the file cannot be created";
      deformation.save_basis(out);
      out.close();
      if(!out)
        throw CGAL::Spectral_deformation_error(CGAL::Spectral_deformation_error::IO_ERROR,
                                               "write error (disk full?)");
    }
    std::filesystem::rename(temporary, file);
    return std::string();
  }
  catch(const std::exception& e)
  {
    std::error_code ignored;
    std::filesystem::remove(temporary, ignored);
    return e.what();
  }
}

// The folder of the basis caches: $XDG_CACHE_HOME/ssmd, else
// $HOME/.cache/ssmd; empty when neither variable is usable. The XDG base
// directory specification says to ignore a relative $XDG_CACHE_HOME.
std::filesystem::path cache_folder()
{
  const char* xdg = std::getenv("XDG_CACHE_HOME");
  if(xdg != nullptr && std::filesystem::path(xdg).is_absolute())
    return std::filesystem::path(xdg) / "ssmd";
  const char* home = std::getenv("HOME");
  if(home != nullptr && *home != '\0')
    return std::filesystem::path(home) / ".cache" / "ssmd";
  return std::filesystem::path();
}

// 64-bit FNV-1a: the cache name only has to tell meshes apart; a collision
// is caught by the fingerprint that load_basis() checks.
struct Fnv1a
{
  std::uint64_t state = 14695981039346656037ull;

  void add(const char* data, std::size_t size)
  {
    for(std::size_t i = 0; i < size; ++i)
    {
      state ^= static_cast<unsigned char>(data[i]);
      state *= 1099511628211ull;
    }
  }
};

// The name of the cache of a basis in the cache folder: the mesh file name
// for the reader, and a hash of what the basis depends on (the content of
// the mesh file, the region of interest, the number of frequencies), so
// that two meshes, even of the same name, or two regions of one mesh never
// share a file.
std::string cache_file_name(const std::string& mesh_file, const std::vector<char>& in_roi,
                            std::size_t frequencies, bool approximate)
{
  Fnv1a hash;
  std::ifstream in(mesh_file, std::ios::binary);
  std::vector<char> buffer(1 << 16);
  while(in.read(buffer.data(), static_cast<std::streamsize>(buffer.size())) || in.gcount() > 0)
    hash.add(buffer.data(), static_cast<std::size_t>(in.gcount()));
  if(in.bad())
    throw Tool_error("cannot read the mesh " + mesh_file + " again to name its basis cache");
  hash.add(in_roi.data(), in_roi.size());
  const std::string m = std::to_string(frequencies);
  hash.add(m.data(), m.size());
  std::ostringstream name;
  name << std::filesystem::path(mesh_file).stem().string() << '-' << std::hex << std::setw(16)
       << std::setfill('0') << hash.state << std::dec << "-m" << frequencies
       << (approximate ? "-approximate" : "") << ".ssmd-basis";
  return name.str();
}

Mesh read_triangle_mesh(const std::string& file)
{
  std::error_code error;
  if(!std::filesystem::exists(file, error))
    throw Tool_error("cannot read the mesh " + file + ": no such file");
  if(std::filesystem::is_directory(file, error))
    throw Tool_error("cannot read the mesh " + file + ": it is a directory");
  errno = 0;
  if(!std::ifstream(file))
    throw Tool_error("cannot read the mesh " + file + ": " +
                     (errno != 0 ? std::strerror(errno) : "the file cannot be opened"));
  Mesh mesh;
  bool read = false;
  try
  {
    read = CGAL::IO::read_polygon_mesh(file, mesh, CGAL::parameters::verbose(false));
  }
  catch(const std::exception&)
  {
    read = false;
  }
  if(!read)
    throw Tool_error("cannot read a polygon mesh from " + file +
                     " (unsupported extension, malformed or truncated file, or polygons that "
                     "do not form a manifold mesh)");
  if(mesh.number_of_faces() == 0)
    throw Tool_error("the mesh " + file + " has no face");
  if(!CGAL::is_triangle_mesh(mesh))
  {
    std::size_t polygons = 0;
    for(Mesh::Face_index f : mesh.faces())
      polygons += (mesh.degree(f) != 3);
    throw Tool_error("the mesh " + file + " is not a triangle mesh: " + std::to_string(polygons) +
                     " of its " + std::to_string(mesh.number_of_faces()) +
                     " faces are not triangles (triangulate it first, e.g. with "
                     "CGAL::Polygon_mesh_processing::triangulate_faces())");
  }
  for(Vertex_index v : mesh.vertices())
  {
    const Point& p = mesh.point(v);
    if(!(std::isfinite(p.x()) && std::isfinite(p.y()) && std::isfinite(p.z())))
      throw Tool_error("the mesh " + file + " has a non-finite coordinate (vertex " +
                       std::to_string(v.idx()) + ")");
  }
  return mesh;
}

// What the report prints at the end.
struct Run_report
{
  double read_mesh_seconds = 0;
  double read_constraints_seconds = 0;
  double cache_seconds = 0;
  double write_seconds = 0;
  double render_seconds = 0;
  std::string basis_origin;
  std::size_t eigensolver_solves = 0;
  bool dense_eigensolve = false;
  bool approximate_eigensolve = false;
  CGAL::Spectral_preprocess_report preprocess;
  CGAL::Spectral_deformation_report deform;
  CGAL::Spectral_refinement_report refinement; // when --refine
  double max_handle_residual = 0; // relative to the bounding-box diagonal of the mesh
};

class Run
{
public:
  explicit Run(const Deformation_tool::Command_line_options& options)
    : m_options(options), m_info(options.quiet ? nullptr : std::cout.rdbuf())
  {}

  int execute()
  {
    const std::string output_file =
        m_options.output_file.empty() ? default_output_file(m_options.mesh_file) : m_options.output_file;
    check_output(output_file);
    if(m_options.render)
    {
      try
      {
        Deformation_tool::check_renderer_available();
      }
      catch(const Deformation_tool::Rendering_error& e)
      {
        throw Tool_error(e.what());
      }
    }

    Clock::time_point start = Clock::now();
    Mesh mesh = read_triangle_mesh(m_options.mesh_file);
    m_report.read_mesh_seconds = seconds_since(start);
    m_info << m_options.mesh_file << ": " << mesh.number_of_vertices() << " vertices, "
           << mesh.number_of_faces() << " triangles\n";

    std::vector<Eigen::Vector3d> rest(mesh.number_of_vertices());
    for(Vertex_index v : mesh.vertices())
      rest[v.idx()] = Eigen::Vector3d(mesh.point(v).x(), mesh.point(v).y(), mesh.point(v).z());

    start = Clock::now();
    Deformation_tool::Deformation_constraints constraints;
    try
    {
      constraints = m_options.constraint_file.empty()
                        ? Deformation_tool::read_selection_files(m_options.selection_file,
                                                                 m_options.transformation_file, rest)
                        : Deformation_tool::read_constraint_file(m_options.constraint_file, rest);
    }
    catch(const Deformation_tool::Constraint_error& e)
    {
      throw Tool_error(e.what());
    }
    m_report.read_constraints_seconds = seconds_since(start);
    m_info << "constraints: " << constraints.number_of_roi_vertices()
           << " vertices in the region of interest, " << constraints.number_of_handle_vertices()
           << " handle vertices\n";

    switch(m_options.algorithm)
    {
    case Deformation_tool::Algorithm::SPECTRAL:
      deform_with_basis<CGAL::SPECTRAL_DUAL_LAPLACIAN>(mesh, constraints);
      break;
    case Deformation_tool::Algorithm::LINEAR:
      deform_with_basis<CGAL::SPECTRAL_LINEAR>(mesh, constraints);
      break;
    case Deformation_tool::Algorithm::SPATIAL:
      deform<CGAL::SPATIAL_DUAL_LAPLACIAN>(mesh, constraints);
      break;
    }

    // The largest distance of a handle vertex to its target, relative to the
    // bounding box of the whole mesh (the deformation's own report measures
    // it against the region).
    Eigen::Vector3d low = rest.front(), high = rest.front();
    for(const Eigen::Vector3d& p : rest)
    {
      low = low.cwiseMin(p);
      high = high.cwiseMax(p);
    }
    const double diagonal = (high - low).norm() > 0 ? (high - low).norm() : 1.0;
    for(Vertex_index v : mesh.vertices())
      if(constraints.is_handle[v.idx()])
      {
        const Point& p = mesh.point(v);
        const double distance = (Eigen::Vector3d(p.x(), p.y(), p.z()) - constraints.targets[v.idx()]).norm();
        m_report.max_handle_residual = std::max(m_report.max_handle_residual, distance / diagonal);
      }

    start = Clock::now();
    write_mesh_atomically(mesh, output_file);
    m_report.write_seconds = seconds_since(start);

    if(m_options.render)
    {
      start = Clock::now();
      render(mesh, rest, output_file);
      m_report.render_seconds = seconds_since(start);
    }
    print_report();
    m_info << "wrote " << output_file << "\n";
    return EXIT_SUCCESS;
  }

private:
  void check_output(const std::string& output_file) const
  {
    const std::filesystem::path output(output_file);
    if(!is_writable_format(lowercase_extension(output)))
      throw Deformation_tool::Usage_error(
          "cannot write the format of '" + output_file +
          "': the output extension must be .off, .obj, .ply, .stl or .ts");
    const std::filesystem::path directory =
        output.parent_path().empty() ? std::filesystem::path(".") : output.parent_path();
    std::error_code error;
    if(!std::filesystem::is_directory(directory, error))
      throw Tool_error("cannot write the result to " + output_file + ": the directory " +
                       directory.string() + " does not exist");
    if(std::filesystem::is_directory(output, error))
      throw Tool_error("cannot write the result to " + output_file + ": it is a directory");
    // Checked before the work rather than found at the end.
    if(::access(directory.c_str(), W_OK) != 0)
      throw Tool_error("cannot write the result to " + output_file + ": the directory " +
                       directory.string() + " is not writable (" + std::strerror(errno) + ")");
  }

  template <class Deformation>
  std::unique_ptr<Deformation> make_deformation(Mesh& mesh,
                                                const Deformation_tool::Deformation_constraints& constraints,
                                                Progress_bar& progress_bar) const
  {
    std::unique_ptr<Deformation> deformation(new Deformation(mesh));
    deformation->set_iterations(m_options.iterations);
    deformation->set_tolerance(m_options.tolerance);
    deformation->set_process_wide_tuning(true); // this program owns its process
    if constexpr(Deformation::has_basis)
    {
      deformation->set_number_of_frequencies(m_options.frequencies);
      if(m_options.rotation_patches >= 0)
        deformation->set_rotation_patches(static_cast<std::size_t>(m_options.rotation_patches));
      if(m_options.single_precision_threshold >= 0)
        deformation->set_single_precision_basis_threshold(
            static_cast<std::size_t>(m_options.single_precision_threshold));
      if(m_options.stage_angle >= 0)
        deformation->set_stage_angle(m_options.stage_angle);
      deformation->set_volume_preservation(m_options.volume_preservation);
      deformation->set_smooth_energy(
          m_options.energy == Deformation_tool::Energy::ARAP ? CGAL::ARAP_ENERGY
          : m_options.energy == Deformation_tool::Energy::DUAL_LAPLACIAN_AND_ARAP
              ? CGAL::DUAL_LAPLACIAN_AND_ARAP_ENERGY
              : CGAL::DUAL_LAPLACIAN_ENERGY);
      deformation->set_constraint_weight(m_options.constraint_weight);
      deformation->set_constraint_policy(m_options.policy == Deformation_tool::Policy::EXACT
                                             ? CGAL::EXACT_CONSTRAINTS
                                             : CGAL::SOFT_CONSTRAINTS);
      if constexpr(Deformation::has_basis)
      {
        typename Deformation::Eigensolver_traits eigensolver;
        eigensolver.set_process_wide_tuning(true); // this program owns its process
        eigensolver.set_progress_callback(
            [&progress_bar](const Eigensolver_traits::Progress& progress) { progress_bar(progress); });
        deformation->set_eigensolver_traits(eigensolver);
      }
    }
    for(Vertex_index v : mesh.vertices())
      if(constraints.in_roi[v.idx()])
        deformation->insert_roi_vertex(v);
    for(Vertex_index v : mesh.vertices())
      if(constraints.is_handle[v.idx()])
        deformation->insert_control_vertex(v);
    return deformation;
  }

  // The basis cache of this run: --basis-cache, or a file of the cache
  // folder, which is created if needed. Clears `use_cache` when there is no
  // usable folder: the run goes on without cache.
  std::string basis_cache_file(const Deformation_tool::Deformation_constraints& constraints,
                               bool& use_cache) const
  {
    if(!m_options.basis_cache_file.empty())
      return m_options.basis_cache_file;
    const std::filesystem::path folder = cache_folder();
    if(folder.empty())
    {
      warn("no cache folder (neither XDG_CACHE_HOME nor HOME is set): the basis is not cached; "
           "--basis-cache FILE names a cache file");
      use_cache = false;
      return std::string();
    }
    std::error_code error;
    std::filesystem::create_directories(folder, error);
    if(error || !std::filesystem::is_directory(folder))
    {
      warn("cannot create the cache folder " + folder.string() + " (" +
           (error ? error.message() : std::string("not a directory")) +
           "): the basis is not cached; --basis-cache FILE names another cache file");
      use_cache = false;
      return std::string();
    }
    return (folder / cache_file_name(m_options.mesh_file, constraints.in_roi, m_options.frequencies,
                                     m_options.approximate_basis))
        .string();
  }

  // Reads the cache into `deformation`; a cache that cannot be used is
  // reported and left to be overwritten.
  template <class Deformation>
  bool load_cache(Deformation& deformation, const std::string& cache_file)
  {
    std::error_code error;
    if(!std::filesystem::exists(cache_file, error))
      return false;
    const Clock::time_point start = Clock::now();
    errno = 0;
    std::ifstream in(cache_file, std::ios::binary);
    if(!in)
    {
      warn("cannot open the basis cache " + cache_file + " (" +
           (errno != 0 ? std::strerror(errno) : "unknown reason") + "): the basis is recomputed");
      return false;
    }
    try
    {
      deformation.load_basis(in);
    }
    catch(const CGAL::Spectral_deformation_error& e)
    {
      warn("the basis cache " + cache_file + " cannot be used (" + e.what() +
           "): the basis is recomputed and the cache rewritten");
      return false;
    }
    m_report.cache_seconds = seconds_since(start);
    return true;
  }

  // deform() for an algorithm with a basis, computed as --basis says.
  template <CGAL::Spectral_deformation_algorithm_tag TAG>
  void deform_with_basis(Mesh& mesh, const Deformation_tool::Deformation_constraints& constraints)
  {
    if(m_options.approximate_basis)
      deform<TAG, Approximate_eigensolver_traits>(mesh, constraints);
    else
      deform<TAG, Eigensolver_traits>(mesh, constraints);
  }

  template <CGAL::Spectral_deformation_algorithm_tag TAG, class ET = CGAL::Default>
  void deform(Mesh& mesh, const Deformation_tool::Deformation_constraints& constraints)
  {
    typedef CGAL::Spectral_surface_mesh_deformation<Mesh, CGAL::Default, CGAL::Default, TAG, ET> Deformation;
    constexpr bool uses_basis = Deformation::has_basis;
    const Deformation_tool::Progress_display display =
        m_options.quiet                ? Deformation_tool::Progress_display::NONE
        : ::isatty(STDERR_FILENO) != 0 ? Deformation_tool::Progress_display::TERMINAL
                                       : Deformation_tool::Progress_display::LOG;
    Progress_bar progress_bar(std::cerr, display, STDERR_FILENO);

    std::unique_ptr<Deformation> deformation;
    try
    {
      deformation = make_deformation<Deformation>(mesh, constraints, progress_bar);
    }
    catch(const CGAL::Spectral_deformation_error& e)
    {
      throw Tool_error(std::string("cannot set up the deformation: ") + e.what());
    }

    bool use_cache = uses_basis && m_options.use_cache;
    const std::string cache_file =
        use_cache ? basis_cache_file(constraints, use_cache) : std::string();
    bool loaded = false;
    if constexpr(uses_basis)
      loaded = use_cache && load_cache(*deformation, cache_file);

    bool prepared = deformation->preprocess();
    progress_bar.finish();
    if(prepared && loaded)
    {
      // A cache given by --basis-cache may hold another number of
      // frequencies, which would prevail: recompute instead.
      const std::size_t expected = std::min(m_options.frequencies,
                                            deformation->preprocess_report().number_of_region_vertices);
      const std::size_t cached = deformation->preprocess_report().number_of_frequencies;
      if(cached != expected)
      {
        warn("the basis cache " + cache_file + " holds " + std::to_string(cached) +
             " frequencies, " + std::to_string(expected) +
             " are requested: the basis is recomputed and the cache rewritten");
        deformation = make_deformation<Deformation>(mesh, constraints, progress_bar);
        loaded = false;
        prepared = deformation->preprocess();
        progress_bar.finish();
      }
    }
    m_report.preprocess = deformation->preprocess_report();
    if(!prepared)
      throw Tool_error("cannot prepare the deformation: " + m_report.preprocess.message);
    m_report.eigensolver_solves = progress_bar.solves();
    m_report.dense_eigensolve = progress_bar.dense();
    m_report.approximate_eigensolve = progress_bar.approximate();

    const std::string kept_in_float = m_report.preprocess.single_precision_basis ? ", kept in float" : "";
    if(!uses_basis)
      m_report.basis_origin = "not used by the spatial algorithm";
    else if(loaded)
      m_report.basis_origin = "loaded from the cache " + cache_file + " (eigensolve skipped)" + kept_in_float;
    else
    {
      std::ostringstream origin;
      origin << "computed in " << std::setprecision(3) << m_report.preprocess.basis_seconds << " s ("
             << (m_report.approximate_eigensolve ? std::string("approximate")
                 : m_report.dense_eigensolve ? std::string("dense solver")
                                             : std::to_string(m_report.eigensolver_solves) + " Lanczos solves")
             << ")" << kept_in_float;
      if constexpr(uses_basis)
      {
        if(use_cache)
        {
          const std::string failure = save_basis_cache(*deformation, cache_file);
          if(failure.empty())
            origin << ", saved to the cache " << cache_file;
          else
            warn("cannot save the basis to the cache " + cache_file + " (" + failure +
                 "): the run goes on, the next one computes the basis again");
        }
      }
      m_report.basis_origin = origin.str();
    }
    m_info << "basis: " << m_report.basis_origin << "\n";

    try
    {
      for(Vertex_index v : mesh.vertices())
        if(constraints.is_handle[v.idx()])
        {
          const Eigen::Vector3d& t = constraints.targets[v.idx()];
          deformation->set_target_position(v, Point(t[0], t[1], t[2]));
        }
    }
    catch(const CGAL::Spectral_deformation_error& e)
    {
      throw Tool_error(std::string("invalid target: ") + e.what());
    }
    deformation->deform();
    m_report.deform = deformation->deform_report();
    if(!m_report.deform.success)
      throw Tool_error("the deformation failed: " + m_report.deform.message);
    if(m_options.refine_tolerance >= 0)
    {
      deformation->refine(m_options.refine_iterations, m_options.refine_tolerance);
      m_report.refinement = deformation->refine_report();
      if(!m_report.refinement.success)
        throw Tool_error("the refinement failed: " + m_report.refinement.message);
    }
  }

  void render(const Mesh& mesh, const std::vector<Eigen::Vector3d>& rest, const std::string& output_file)
  {
    std::error_code error;
    const std::filesystem::path directory =
        std::filesystem::temp_directory_path(error) / ("ssmd_deform-" + std::to_string(::getpid()));
    std::filesystem::create_directories(directory, error);
    if(error)
      throw Tool_error("cannot create the temporary directory " + directory.string());
    const std::string before_mesh = (directory / "before.ply").string();
    const std::string after_mesh = (directory / "after.ply").string();
    Mesh before = mesh;
    Eigen::Vector3d low = rest.front(), high = rest.front();
    for(Vertex_index v : before.vertices())
    {
      const Eigen::Vector3d& p = rest[v.idx()];
      before.point(v) = Point(p[0], p[1], p[2]);
      const Point& q = mesh.point(v);
      const Eigen::Vector3d deformed(q.x(), q.y(), q.z());
      low = low.cwiseMin(p).cwiseMin(deformed);
      high = high.cwiseMax(p).cwiseMax(deformed);
    }
    const std::filesystem::path output(output_file);
    const std::string stem = (output.parent_path() / output.stem()).string();
    try
    {
      if(!CGAL::IO::write_polygon_mesh(before_mesh, before) ||
         !CGAL::IO::write_polygon_mesh(after_mesh, mesh))
        throw Tool_error("cannot write the meshes to render into " + directory.string());
      Deformation_tool::render_before_after(before_mesh, after_mesh, stem + "_before.png",
                                            stem + "_after.png", low, high,
                                            (directory / "f3d.log").string());
    }
    catch(const Deformation_tool::Rendering_error& e)
    {
      std::filesystem::remove_all(directory, error);
      throw Tool_error(e.what());
    }
    catch(...)
    {
      std::filesystem::remove_all(directory, error);
      throw;
    }
    std::filesystem::remove_all(directory, error);
    m_info << "rendered " << stem << "_before.png and " << stem << "_after.png\n";
  }

  void print_report()
  {
    const CGAL::Spectral_preprocess_report& pre = m_report.preprocess;
    const CGAL::Spectral_deformation_report& def = m_report.deform;
    auto row = [this](const std::string& phase, double seconds, const std::string& note = std::string()) {
      m_info << "  " << std::left << std::setw(28) << phase << std::right << std::setw(10)
             << std::fixed << std::setprecision(3) << seconds << " s";
      if(!note.empty())
        m_info << "   " << note;
      m_info << "\n";
      m_info.unsetf(std::ios::fixed);
    };
    m_info << "timings:\n";
    row("read mesh", m_report.read_mesh_seconds);
    row("read constraints", m_report.read_constraints_seconds);
    if(m_report.cache_seconds > 0)
      row("read basis cache", m_report.cache_seconds);
    row("region (basis included)", pre.region_seconds,
        std::to_string(pre.number_of_region_vertices) + " vertices");
    if(pre.basis_computed)
      row("  of which eigensolve", pre.basis_seconds,
          std::to_string(pre.number_of_frequencies) + " frequencies");
    row("factorization", pre.factorization_seconds,
        std::to_string(pre.number_of_constrained_vertices) + " constrained vertices");
    row("solve", def.solve_seconds, std::to_string(def.iterations) + " iterations");
    row("detail transfer", def.detail_transfer_seconds);
    const CGAL::Spectral_refinement_report& refinement = m_report.refinement;
    if(refinement.success)
      row("refinement", refinement.total_seconds, std::to_string(refinement.iterations) + " iterations");
    row("write result", m_report.write_seconds);
    if(m_options.render)
      row("render", m_report.render_seconds);
    m_info << "iterations: " << def.iterations << " ("
           << (def.converged ? "converged" : "stopped at the iteration cap") << ", last relative step "
           << std::setprecision(3) << def.last_step << ")\n";
    if(refinement.success)
      m_info << "refinement: " << refinement.iterations << " iterations ("
             << (refinement.converged ? "converged" : "stopped at the iteration cap") << "), ARAP energy "
             << std::setprecision(4) << refinement.energy_before << " -> " << refinement.energy_after
             << (refinement.volume_preserved ? ", enclosed volume kept" : "") << "\n";
    if(def.stages > 1)
      m_info << "stages: " << def.stages << " (a handle turned by more than the stage angle)\n";
    if(m_options.volume_preservation && m_options.algorithm != Deformation_tool::Algorithm::SPATIAL)
      m_info << (def.volume_preserved ? "enclosed volume kept\n"
                                      : "enclosed volume not defined (the surface around the region is open): "
                                        "not kept\n");
    m_info << "max handle residual: " << std::setprecision(3) << m_report.max_handle_residual
           << " of the bounding-box diagonal of the mesh\n";
  }

  void warn(const std::string& message) const
  {
    std::cerr << program_name << ": warning: " << message << "\n";
  }

  const Deformation_tool::Command_line_options& m_options;
  std::ostream m_info; // standard output, or nothing with --quiet
  Run_report m_report;
};

} // namespace

int main(int argc, char** argv)
{
  const std::string hint = std::string("Try '") + program_name + " --help' for more information.\n";
  try
  {
    const Deformation_tool::Command_line_options options =
        Deformation_tool::parse_command_line(argc, argv);
    if(options.help)
    {
      std::cout << options.help_text;
      return EXIT_SUCCESS;
    }
    if(options.version)
    {
      std::cout << program_name << " " << program_version << "\n";
      return EXIT_SUCCESS;
    }
    Run run(options);
    return run.execute();
  }
  catch(const Deformation_tool::Usage_error& e)
  {
    std::cerr << program_name << ": error: " << e.what() << "\n" << hint;
    return 2;
  }
  catch(const Tool_error& e)
  {
    std::cerr << program_name << ": error: " << e.what() << "\n";
  }
  catch(const std::bad_alloc&)
  {
    std::cerr << program_name << ": error: out of memory\n";
  }
  catch(const std::exception& e)
  {
    std::cerr << program_name << ": error: " << e.what() << "\n";
  }
  return EXIT_FAILURE;
}
