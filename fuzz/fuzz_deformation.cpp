// Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Fuzzes the whole deformation: a small mesh derived from the input (grid,
// tetrahedron, octahedron, tube or random soup; scaled from 1e-9 to 1e9,
// jittered, with collapsed, needle, duplicated, quad and isolated elements,
// NaN, infinite and huge coordinates), then a random sequence of calls of
// the API of Spectral_surface_mesh_deformation (ROI and control vertices,
// also ones not in the mesh; targets, also NaN, infinite or huge; rotations,
// parameters, preprocess, deform, reset, basis cache round trips) with one
// of the three algorithms.
//
// Property, after every call: either Spectral_deformation_error was thrown
// (and the mesh is untouched), or the call did what its documentation says:
// a failed preprocess()/deform() leaves the mesh untouched except that
// vertices erased from the ROI return to their initial positions; a
// successful deform() writes finite positions into the ROI only; control
// vertices are ROI vertices; targets stay finite.
#include "fuzz_common.h"

#include <CGAL/Spectral_surface_mesh_deformation.h>

#include <fuzzer/FuzzedDataProvider.h>

#include <Eigen/Geometry>

#include <array>
#include <cstdlib>
#include <limits>
#include <sstream>

namespace {

using namespace ssmd_fuzz;
typedef CGAL::Spectral_deformation_error Error;

// ---------------------------------------------------------------------------
// Mesh from the input.

struct Soup
{
  std::vector<std::array<double, 3>> points;
  std::vector<std::vector<std::size_t>> faces;
};

void grid(FuzzedDataProvider& in, Soup& soup)
{
  const int w = in.ConsumeIntegralInRange(1, 5), h = in.ConsumeIntegralInRange(1, 5);
  const bool quads = in.ConsumeBool();
  for(int j = 0; j <= h; ++j)
    for(int i = 0; i <= w; ++i)
      soup.points.push_back({double(i), double(j), 0.1 * ((i * 5 + j * 3) % 4)});
  auto id = [&](int i, int j) { return std::size_t(j * (w + 1) + i); };
  for(int j = 0; j < h; ++j)
    for(int i = 0; i < w; ++i)
    {
      if(quads && (i + j) % 3 == 0)
        soup.faces.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)});
      else
      {
        soup.faces.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
        soup.faces.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
      }
    }
}

void tube(FuzzedDataProvider& in, Soup& soup)
{
  const int ring = in.ConsumeIntegralInRange(3, 7), rings = in.ConsumeIntegralInRange(1, 5);
  const bool capped = in.ConsumeBool();
  for(int r = 0; r <= rings; ++r)
    for(int k = 0; k < ring; ++k)
    {
      const double a = 2 * 3.14159265358979 * k / ring;
      soup.points.push_back({std::cos(a), std::sin(a), double(r)});
    }
  auto id = [&](int r, int k) { return std::size_t(r * ring + (k % ring)); };
  for(int r = 0; r < rings; ++r)
    for(int k = 0; k < ring; ++k)
    {
      soup.faces.push_back({id(r, k), id(r, k + 1), id(r + 1, k + 1)});
      soup.faces.push_back({id(r, k), id(r + 1, k + 1), id(r + 1, k)});
    }
  if(capped)
  {
    const std::size_t bottom = soup.points.size();
    soup.points.push_back({0, 0, 0});
    const std::size_t top = soup.points.size();
    soup.points.push_back({0, 0, double(rings)});
    for(int k = 0; k < ring; ++k)
    {
      soup.faces.push_back({bottom, id(0, k + 1), id(0, k)});
      soup.faces.push_back({top, id(rings, k), id(rings, k + 1)});
    }
  }
}

void polyhedron(FuzzedDataProvider& in, Soup& soup)
{
  if(in.ConsumeBool())
  {
    soup.points = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    soup.faces = {{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {0, 3, 2}};
  }
  else
  {
    soup.points = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
    soup.faces = {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4},
                  {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}};
  }
}

void random_soup(FuzzedDataProvider& in, Soup& soup)
{
  const std::size_t n = in.ConsumeIntegralInRange<std::size_t>(3, 14);
  for(std::size_t i = 0; i < n; ++i)
    soup.points.push_back({in.ConsumeIntegralInRange(-4, 4) * 0.5, in.ConsumeIntegralInRange(-4, 4) * 0.5,
                           in.ConsumeIntegralInRange(-4, 4) * 0.5});
  const int faces = in.ConsumeIntegralInRange(1, 20);
  for(int f = 0; f < faces; ++f)
  {
    std::vector<std::size_t> face(in.ConsumeIntegralInRange<std::size_t>(3, 4));
    for(std::size_t& i : face)
      i = in.ConsumeIntegralInRange<std::size_t>(0, n - 1);
    soup.faces.push_back(face);
  }
}

double special_value(FuzzedDataProvider& in)
{
  switch(in.ConsumeIntegralInRange(0, 5))
  {
    case 0: return std::numeric_limits<double>::quiet_NaN();
    case 1: return std::numeric_limits<double>::infinity();
    case 2: return -std::numeric_limits<double>::infinity();
    case 3: return 1e300;
    case 4: return std::numeric_limits<double>::denorm_min();
    default: return -1e154;
  }
}

// Builds the mesh; also returns which vertex slots exist.
Mesh make_mesh(FuzzedDataProvider& in)
{
  Soup soup;
  switch(in.ConsumeIntegralInRange(0, 4))
  {
    case 0: grid(in, soup); break;
    case 1: tube(in, soup); break;
    case 2: polyhedron(in, soup); break;
    case 3: random_soup(in, soup); break;
    default:
      grid(in, soup);
      {
        // A second component, shifted.
        Soup other;
        polyhedron(in, other);
        const std::size_t offset = soup.points.size();
        for(auto p : other.points)
          soup.points.push_back({p[0] + 10, p[1], p[2]});
        for(auto f : other.faces)
        {
          for(std::size_t& i : f)
            i += offset;
          soup.faces.push_back(f);
        }
      }
  }
  // Scale, offset and jitter.
  const double scale = std::pow(10.0, in.ConsumeIntegralInRange(-9, 9));
  const double offset = in.ConsumeBool() ? scale * in.ConsumeIntegralInRange(-1000, 1000) : 0.0;
  const bool jitter = in.ConsumeBool();
  for(auto& p : soup.points)
    for(double& c : p)
      c = scale * (c + (jitter ? in.ConsumeIntegralInRange(-8, 8) * 0.01 : 0.0)) + offset;
  // Defects.
  const int defects = in.ConsumeIntegralInRange(0, 3);
  for(int d = 0; d < defects && !soup.points.empty(); ++d)
  {
    const std::size_t n = soup.points.size();
    const std::size_t a = in.ConsumeIntegralInRange<std::size_t>(0, n - 1);
    const std::size_t b = in.ConsumeIntegralInRange<std::size_t>(0, n - 1);
    const std::size_t c = in.ConsumeIntegralInRange<std::size_t>(0, n - 1);
    switch(in.ConsumeIntegralInRange(0, 6))
    {
      case 0: soup.points[a] = soup.points[b]; break;                      // collapsed edges
      case 1:                                                              // needle: a on [b, c]
        for(int k = 0; k < 3; ++k)
          soup.points[a][k] = 0.5 * (soup.points[b][k] + soup.points[c][k]) + 1e-13 * scale;
        break;
      case 2: soup.points[a][in.ConsumeIntegralInRange(0, 2)] = special_value(in); break;
      case 3: soup.points.push_back(soup.points[a]); break;                // isolated duplicate
      case 4:                                                              // duplicate vertex used by a face
        soup.points.push_back(soup.points[a]);
        soup.faces.push_back({n, b, c});
        break;
      case 5:                                                              // duplicated face
        if(!soup.faces.empty())
        {
          std::vector<std::size_t> f = soup.faces[a % soup.faces.size()];
          if(in.ConsumeBool())
            std::reverse(f.begin(), f.end());
          soup.faces.push_back(f);
        }
        break;
      default: soup.faces.push_back({a, b, c}); break;                      // arbitrary face
    }
  }
  Mesh mesh;
  std::vector<Vertex> vertex;
  for(const auto& p : soup.points)
    vertex.push_back(mesh.add_vertex(Point(p[0], p[1], p[2])));
  for(const auto& f : soup.faces)
  {
    std::vector<Vertex> face;
    for(std::size_t i : f)
      face.push_back(vertex[i]);
    bool distinct = true;
    for(std::size_t i = 0; i < face.size(); ++i)
      for(std::size_t j = i + 1; j < face.size(); ++j)
        distinct = distinct && face[i] != face[j];
    if(distinct)
      mesh.add_face(face); // refuses non-manifold faces (null face)
  }
  if(in.ConsumeIntegralInRange(0, 15) == 0)
    mesh.remove_vertex(mesh.add_vertex(Point(0, 0, 0))); // garbage left uncollected
  return mesh;
}

// ---------------------------------------------------------------------------
// The API sequence.

// SSMD_FUZZ_TRACE=1 prints every call, to replay a finding.
bool trace()
{
  static const bool enabled = std::getenv("SSMD_FUZZ_TRACE") != nullptr;
  return enabled;
}

template <CGAL::Spectral_deformation_algorithm_tag TAG>
class Session
{
  typedef CGAL::Spectral_surface_mesh_deformation<Mesh, CGAL::Default, CGAL::Default, TAG> Deformation;

public:
  Session(Mesh& mesh, FuzzedDataProvider& in) : m_mesh(mesh), m_in(in) {}

  void run()
  {
    std::unique_ptr<Deformation> deformation;
    const std::vector<Point> before = positions(m_mesh);
    try
    {
      deformation.reset(new Deformation(m_mesh));
    }
    catch(const Error& e)
    {
      require(e.code() == Error::INVALID_MESH, "constructor: unexpected error code");
      require(same_positions(positions(m_mesh), before), "a failed constructor changed the mesh");
      return;
    }
    catch(...)
    {
      violation("constructor: undocumented exception");
    }
    m_original = before;
    Deformation& d = *deformation;
    const int calls = m_in.ConsumeIntegralInRange(1, 24);
    for(int call = 0; call < calls && m_in.remaining_bytes() > 0; ++call)
      step(d);
    // Always end with a deformation.
    check_call(d, 9, [&] { d.deform(); });
  }

private:
  std::size_t slots() const { return m_mesh.number_of_vertices() + m_mesh.number_of_removed_vertices(); }

  // A vertex slot, a removed vertex, the null vertex or an index beyond the mesh.
  Vertex any_vertex()
  {
    const std::size_t n = slots();
    const std::size_t i = m_in.ConsumeIntegralInRange<std::size_t>(0, n + 1);
    if(i == n)
      return Vertex();
    return Vertex(static_cast<Mesh::size_type>(i));
  }

  Eigen::Vector3d vector(double scale)
  {
    if(m_in.ConsumeIntegralInRange(0, 9) == 0)
      return Eigen::Vector3d(special_value(m_in), 0, scale);
    return scale * Eigen::Vector3d(m_in.ConsumeIntegralInRange(-10, 10), m_in.ConsumeIntegralInRange(-10, 10),
                                   m_in.ConsumeIntegralInRange(-10, 10)) / 10.0;
  }

  double mesh_scale() const
  {
    double largest = 1e-300;
    for(Vertex v : m_mesh.vertices())
    {
      const Point& p = m_mesh.point(v);
      for(double c : {p.x(), p.y(), p.z()})
        if(std::isfinite(c))
          largest = std::max(largest, std::abs(c));
    }
    return largest;
  }

  void step(Deformation& d)
  {
    const int op = m_in.ConsumeIntegralInRange(0, 18);
    const double scale = mesh_scale();
    switch(op)
    {
      case 0: { const Vertex v = any_vertex(); check_call(d, op, [&] { d.insert_roi_vertex(v); }); break; }
      case 1:
      {
        // A run of consecutive vertices into the ROI.
        const std::size_t n = slots(), a = m_in.ConsumeIntegralInRange<std::size_t>(0, n);
        const std::size_t b = m_in.ConsumeIntegralInRange<std::size_t>(a, n);
        std::vector<Vertex> range;
        for(std::size_t i = a; i < b; ++i)
          if(!m_mesh.is_removed(Vertex(static_cast<Mesh::size_type>(i))))
            range.push_back(Vertex(static_cast<Mesh::size_type>(i)));
        check_call(d, op, [&] { d.insert_roi_vertices(range.begin(), range.end()); });
        break;
      }
      case 2: { const Vertex v = any_vertex(); check_call(d, op, [&] { d.insert_control_vertex(v); }); break; }
      case 3: { const Vertex v = any_vertex(); check_call(d, op, [&] { d.erase_roi_vertex(v); }); break; }
      case 4: { const Vertex v = any_vertex(); check_call(d, op, [&] { d.erase_control_vertex(v); }); break; }
      case 5:
      {
        const Vertex v = any_vertex();
        const Eigen::Vector3d t = vector(scale);
        const Point p = (d.is_control_vertex(v) ? d.target_position(v) : Point(0, 0, 0));
        const Point target(p.x() + t[0], p.y() + t[1], p.z() + t[2]);
        check_call(d, op, [&] { d.set_target_position(v, target); });
        break;
      }
      case 6:
      {
        const Eigen::Vector3d t = vector(scale);
        std::vector<Vertex> controls = control_vertices(d);
        check_call(d, op, [&] { d.translate(controls.begin(), controls.end(), t); });
        break;
      }
      case 7:
      {
        const Eigen::Vector3d axis = Eigen::Vector3d(m_in.ConsumeIntegralInRange(-3, 3), m_in.ConsumeIntegralInRange(-3, 3), 1).normalized();
        const double angle = m_in.ConsumeIntegralInRange(-12, 12) * 0.5;
        const Eigen::Quaterniond q(Eigen::AngleAxisd(angle, axis));
        const Eigen::Vector3d center = vector(scale);
        std::vector<Vertex> controls = control_vertices(d);
        check_call(d, op, [&] { d.rotate(controls.begin(), controls.end(), center, q); });
        break;
      }
      case 8: check_call(d, op, [&] { d.preprocess(); }); break;
      case 9: check_call(d, op, [&] { d.deform(); }); break;
      case 10:
      {
        const unsigned int iterations = m_in.ConsumeIntegralInRange(0u, 6u);
        const double tolerance = m_in.ConsumeBool() ? 0.0 : std::pow(10.0, -m_in.ConsumeIntegralInRange(0, 12));
        check_call(d, 9, [&] { d.deform(iterations, tolerance); });
        break;
      }
      case 11: check_call(d, op, [&] { d.reset(); }); break;
      case 12: check_call(d, op, [&] { d.overwrite_initial_geometry(); }); break;
      case 13:
      {
        const std::size_t m = m_in.ConsumeIntegralInRange<std::size_t>(0, slots() + 3);
        if constexpr(Deformation::has_basis)
          check_call(d, op, [&] { d.set_number_of_frequencies(m); });
        break;
      }
      case 14:
      {
        double w = std::pow(10.0, m_in.ConsumeIntegralInRange(-6, 6));
        if(m_in.ConsumeIntegralInRange(0, 3) == 0)
          w = m_in.ConsumeBool() ? 0.0 : special_value(m_in);
        if constexpr(Deformation::has_basis)
          check_call(d, op, [&] { d.set_constraint_weight(w); });
        break;
      }
      case 15:
      {
        const auto policy = m_in.ConsumeBool() ? CGAL::EXACT_CONSTRAINTS : CGAL::SOFT_CONSTRAINTS;
        if constexpr(Deformation::has_basis)
          check_call(d, op, [&] { d.set_constraint_policy(policy); });
        break;
      }
      case 16:
      {
        // Basis cache round trip, the file possibly damaged.
        const int damage = m_in.ConsumeIntegralInRange(0, 2);
        const std::size_t where = m_in.ConsumeIntegral<std::uint16_t>();
        if constexpr(Deformation::has_basis)
        check_call(d, op, [&] {
          std::ostringstream out;
          d.save_basis(out);
          std::string bytes = out.str();
          if(damage == 1 && !bytes.empty())
            bytes[where % bytes.size()] ^= 0x5a;
          else if(damage == 2)
            bytes.resize(where % (bytes.size() + 1));
          std::istringstream is(bytes);
          d.load_basis(is);
        });
        break;
      }
      case 17:
        if(m_in.ConsumeBool())
          check_call(d, op, [&] { d.clear_roi_vertices(); });
        else
          check_call(d, op, [&] { d.clear_control_vertices(); });
        break;
      default:
      {
        const unsigned int iterations = m_in.ConsumeIntegralInRange(0u, 6u);
        double tolerance = std::pow(10.0, -m_in.ConsumeIntegralInRange(0, 12));
        if(m_in.ConsumeIntegralInRange(0, 3) == 0)
          tolerance = special_value(m_in);
        check_call(d, op, [&] {
          d.set_iterations(iterations);
          d.set_tolerance(tolerance);
        });
      }
    }
  }

  std::vector<Vertex> control_vertices(const Deformation& d) const
  {
    std::vector<Vertex> controls;
    for(Vertex v : d.roi_vertices())
      if(d.is_control_vertex(v))
        controls.push_back(v);
    return controls;
  }

  // Runs one call and checks the property.
  template <class Call>
  void check_call(Deformation& d, int op, Call call)
  {
    const std::vector<Point> before = positions(m_mesh);
    const std::vector<Vertex> roi_before = d.roi_vertices();
    bool threw = false;
    try
    {
      call();
    }
    catch(const Error& e)
    {
      threw = true;
      require(std::string(e.what()).size() > 0, "an error without a message");
    }
    catch(...)
    {
      violation("call " + std::to_string(op) + ": undocumented exception");
    }
    const std::vector<Point> after = positions(m_mesh);
    if(trace())
      std::fprintf(stderr, "call %d%s; preprocess: %s; deform: %s\n", op, threw ? " threw" : "",
                   d.preprocess_report().message.c_str(), d.deform_report().message.c_str());
    if(threw)
      require(same_positions(before, after), "call " + std::to_string(op) + " threw and changed the mesh");

    // Structural invariants.
    for(Vertex v : d.roi_vertices())
      require(d.is_roi_vertex(v), "roi_vertices() lists a vertex that is not in the ROI");
    for(std::size_t i = 0; i < slots(); ++i)
    {
      const Vertex v(static_cast<Mesh::size_type>(i));
      if(d.is_control_vertex(v))
      {
        require(d.is_roi_vertex(v), "a control vertex outside the ROI");
        // A target is set finite, or is the position of its vertex (which
        // may be non-finite in the input).
        const Point& target = d.target_position(v);
        require(finite_point(target) || same_point(target, m_mesh.point(v)) ||
                    same_point(target, m_original[i]),
                "a non-finite target was stored");
      }
    }

    // What may move. Vertices outside the ROI only ever go back to their
    // initial positions (preprocess() puts vertices erased from the ROI back).
    std::vector<char> in_roi(after.size(), 0);
    for(Vertex v : roi_before)
      in_roi[v] = 1;
    const bool writes = (op == 8 || op == 9 || op == 11);
    const bool deformed = (op == 9 && d.deform_report().success);
    for(std::size_t i = 0; i < after.size(); ++i)
    {
      if(same_point(before[i], after[i]))
        continue;
      if(trace())
        std::fprintf(stderr, "  vertex %zu: (%g %g %g) -> (%g %g %g), initial (%g %g %g), in the ROI %d\n", i,
                     before[i].x(), before[i].y(), before[i].z(), after[i].x(), after[i].y(), after[i].z(),
                     m_original[i].x(), m_original[i].y(), m_original[i].z(), int(in_roi[i]));
      require(writes, "call " + std::to_string(op) + " moved a vertex");
      const bool back_to_initial = same_point(after[i], m_original[i]);
      if(op == 11)
        require(in_roi[i] && back_to_initial, "reset() moved a vertex elsewhere than its initial position");
      else if(deformed && in_roi[i])
        require(finite_point(after[i]), "deform() wrote a non-finite position");
      else
        require(back_to_initial && !d.is_roi_vertex(Vertex(static_cast<Mesh::size_type>(i))),
                "call " + std::to_string(op) + " moved a vertex that it must not move (" +
                    (op == 9 ? d.deform_report().message : d.preprocess_report().message) + ")");
    }
    if(op == 9)
    {
      const auto& report = d.deform_report();
      if(report.success)
      {
        // Residuals of targets beyond about 1e154 overflow to infinity (a
        // documented limitation); NaN would be a bug.
        require(!std::isnan(report.max_control_residual) && !std::isnan(report.rms_control_residual),
                "deform(): NaN residuals reported");
        // Vertices that no face joins to the region (isolated ROI vertices)
        // are not written: they keep their input position, finite or not.
        for(Vertex v : d.roi_vertices())
          require(finite_point(m_mesh.point(v)) || same_point(m_mesh.point(v), before[v]),
                  "deform() left a non-finite ROI vertex");
      }
      else
        require(!report.message.empty(), "deform() failed without a message");
    }
    if(op == 8 && !d.preprocess_report().success)
      require(!d.preprocess_report().message.empty(), "preprocess() failed without a message");
    if(op == 12 && !threw)
      for(Vertex v : d.roi_vertices())
        m_original[v] = m_mesh.point(v);
  }

  Mesh& m_mesh;
  FuzzedDataProvider& m_in;
  std::vector<Point> m_original;
};

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  FuzzedDataProvider in(data, size);
  const int algorithm = in.ConsumeIntegralInRange(0, 2);
  Mesh mesh = make_mesh(in);
  switch(algorithm)
  {
    case 0: Session<CGAL::SPECTRAL_DUAL_LAPLACIAN>(mesh, in).run(); break;
    case 1: Session<CGAL::SPECTRAL_LINEAR>(mesh, in).run(); break;
    default: Session<CGAL::SPATIAL_DUAL_LAPLACIAN>(mesh, in).run(); break;
  }
  return 0;
}
