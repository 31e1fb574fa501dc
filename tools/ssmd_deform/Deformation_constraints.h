// Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The constraints of the command-line tool ssmd_deform: which vertices form
// the region of interest, which are handles, and where the handles go. They
// come either from a .sel/.def pair (the format of the Botsch and Sorkine
// 2008 benchmark) or from a plain-text constraint file, described in
// doc/command_line_tool.md and by `ssmd_deform --help`.

#ifndef SSMD_TOOLS_DEFORMATION_CONSTRAINTS_H
#define SSMD_TOOLS_DEFORMATION_CONSTRAINTS_H

#include <CGAL/Spectral_deformation/IO/deformation_selection.h>

#include <Eigen/Dense>
#include <Eigen/Geometry>

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <istream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace Deformation_tool {

/// A failure to read constraints; the message names the file and, for the
/// text format, the line.
class Constraint_error : public std::runtime_error
{
public:
  explicit Constraint_error(const std::string& what) : std::runtime_error(what) {}
};

/// Per vertex (indexed like the mesh: vertex `i` is the `i`-th vertex of the
/// mesh as read): whether it is in the region of interest, whether it is a
/// handle (control) vertex, and the target of each handle vertex.
/// Handles are always in the region of interest.
struct Deformation_constraints
{
  std::vector<char> in_roi;
  std::vector<char> is_handle;
  std::vector<Eigen::Vector3d> targets;

  std::size_t number_of_roi_vertices() const { return count(in_roi); }
  std::size_t number_of_handle_vertices() const { return count(is_handle); }

private:
  static std::size_t count(const std::vector<char>& flags)
  {
    std::size_t result = 0;
    for(char flag : flags)
      result += (flag != 0);
    return result;
  }
};

namespace internal {

// Strict number parsing: the whole word must be a number.
inline bool parse_real(const std::string& word, double& value)
{
  if(word.empty())
    return false;
  const char* begin = word.c_str();
  char* end = nullptr;
  errno = 0;
  value = std::strtod(begin, &end);
  return end == begin + word.size() && errno != ERANGE && std::isfinite(value);
}

inline bool parse_index(const std::string& word, std::size_t& value)
{
  if(word.empty() || word.size() > 18)
    return false;
  value = 0;
  for(char c : word)
  {
    if(c < '0' || c > '9')
      return false;
    value = 10 * value + static_cast<std::size_t>(c - '0');
  }
  return true;
}

// Reads the statements of a constraint file; see read_constraint_file().
class Constraint_file_reader
{
public:
  Constraint_file_reader(const std::string& name, const std::vector<Eigen::Vector3d>& positions)
    : m_name(name), m_positions(positions), m_motion(Eigen::Affine3d::Identity())
  {
    const std::size_t n = positions.size();
    m_roi_line.assign(n, 0);
    m_fixed_line.assign(n, 0);
    m_handle_line.assign(n, 0);
    m_target_line.assign(n, 0);
    m_explicit_target.assign(n, Eigen::Vector3d::Zero());
  }

  Deformation_constraints read(std::istream& is)
  {
    std::string line;
    while(std::getline(is, line))
    {
      ++m_line_number;
      const std::size_t hash = line.find('#');
      std::istringstream stream(line.substr(0, hash));
      std::vector<std::string> words;
      for(std::string word; stream >> word;)
        words.push_back(word);
      if(!words.empty())
        statement(words);
    }
    if(is.bad())
      fail_file("the file could not be read");
    return finish();
  }

private:
  void statement(const std::vector<std::string>& words)
  {
    const std::string& keyword = words[0];
    const std::vector<std::string> arguments(words.begin() + 1, words.end());
    if(keyword == "roi")
      select(arguments, m_roi_line, "roi");
    else if(keyword == "fixed")
      select(arguments, m_fixed_line, "fixed");
    else if(keyword == "handle")
    {
      select(arguments, m_handle_line, "handle");
      m_has_handle_statement = true;
    }
    else if(keyword == "translate")
    {
      const std::vector<double> t = numbers(arguments, 3, "translate x y z");
      m_motion = Eigen::Translation3d(t[0], t[1], t[2]) * m_motion;
    }
    else if(keyword == "rotate")
      rotate(arguments);
    else if(keyword == "target")
      target(arguments);
    else
      fail("unknown statement '" + keyword +
           "' (expected roi, fixed, handle, translate, rotate or target)");
  }

  // A selection: `all`, `box xmin ymin zmin xmax ymax zmax`,
  // `sphere cx cy cz radius`, or vertex ids and inclusive ranges `a-b`.
  void select(const std::vector<std::string>& arguments, std::vector<std::size_t>& line_of,
              const std::string& keyword)
  {
    if(arguments.empty())
      fail("'" + keyword + "' expects 'all', 'box ...', 'sphere ...' or vertex ids");
    std::size_t selected = 0;
    auto mark = [&](std::size_t v) {
      if(line_of[v] == 0)
        line_of[v] = m_line_number;
      ++selected;
    };
    const std::string& kind = arguments[0];
    if(kind == "all")
    {
      if(arguments.size() != 1)
        fail("'" + keyword + " all' takes no further argument");
      for(std::size_t v = 0; v < m_positions.size(); ++v)
        mark(v);
    }
    else if(kind == "box")
    {
      const std::vector<double> b = numbers(tail(arguments), 6,
                                            keyword + " box xmin ymin zmin xmax ymax zmax");
      const Eigen::Vector3d low(b[0], b[1], b[2]), high(b[3], b[4], b[5]);
      if((high - low).minCoeff() < 0)
        fail("the box is empty: a minimum is larger than its maximum");
      for(std::size_t v = 0; v < m_positions.size(); ++v)
        if((m_positions[v] - low).minCoeff() >= 0 && (high - m_positions[v]).minCoeff() >= 0)
          mark(v);
    }
    else if(kind == "sphere")
    {
      const std::vector<double> s = numbers(tail(arguments), 4,
                                            keyword + " sphere cx cy cz radius");
      const Eigen::Vector3d center(s[0], s[1], s[2]);
      if(s[3] < 0)
        fail("the radius of the sphere is negative");
      for(std::size_t v = 0; v < m_positions.size(); ++v)
        if((m_positions[v] - center).norm() <= s[3])
          mark(v);
    }
    else
    {
      for(const std::string& word : arguments)
      {
        const std::size_t dash = word.find('-', 1);
        std::size_t first = 0, last = 0;
        const bool valid = (dash == std::string::npos)
                               ? (parse_index(word, first) && (last = first, true))
                               : (parse_index(word.substr(0, dash), first) &&
                                  parse_index(word.substr(dash + 1), last));
        if(!valid)
          fail("expected a vertex id or a range a-b, got '" + word + "'");
        if(first > last)
          fail("the range '" + word + "' is empty");
        if(last >= m_positions.size())
          fail("vertex id " + std::to_string(last) + " is out of range (the mesh has " +
               std::to_string(m_positions.size()) + " vertices, ids 0 to " +
               std::to_string(m_positions.size() - 1) + ")");
        for(std::size_t v = first; v <= last; ++v)
          mark(v);
      }
    }
    if(selected == 0)
      fail("'" + keyword + " " + kind + "' selects no vertex");
  }

  // rotate ax ay az angle_degrees cx cy cz
  void rotate(const std::vector<std::string>& arguments)
  {
    const std::vector<double> r =
        numbers(arguments, 7, "rotate axis_x axis_y axis_z angle_degrees center_x center_y center_z");
    const Eigen::Vector3d axis(r[0], r[1], r[2]), center(r[4], r[5], r[6]);
    if(!(axis.norm() > 0))
      fail("the rotation axis is the zero vector");
    const double angle = r[3] * 3.14159265358979323846 / 180.0;
    m_motion = Eigen::Translation3d(center) * Eigen::AngleAxisd(angle, axis.normalized()) *
               Eigen::Translation3d(-center) * m_motion;
  }

  // target id x y z
  void target(const std::vector<std::string>& arguments)
  {
    if(arguments.size() != 4)
      fail("'target' expects a vertex id and three coordinates: target id x y z");
    std::size_t v = 0;
    if(!parse_index(arguments[0], v))
      fail("expected a vertex id, got '" + arguments[0] + "'");
    if(v >= m_positions.size())
      fail("vertex id " + std::to_string(v) + " is out of range (the mesh has " +
           std::to_string(m_positions.size()) + " vertices)");
    if(m_target_line[v] != 0)
      fail("vertex " + std::to_string(v) + " already has a target (line " +
           std::to_string(m_target_line[v]) + ")");
    const std::vector<double> p = numbers(tail(arguments), 3,
                                          "target id x y z");
    m_target_line[v] = m_line_number;
    m_explicit_target[v] = Eigen::Vector3d(p[0], p[1], p[2]);
  }

  static std::vector<std::string> tail(const std::vector<std::string>& words)
  {
    return std::vector<std::string>(words.begin() + 1, words.end());
  }

  std::vector<double> numbers(const std::vector<std::string>& words, std::size_t expected,
                              const std::string& usage)
  {
    if(words.size() != expected)
      fail("expected " + std::to_string(expected) + " numbers, got " +
           std::to_string(words.size()) + " (usage: " + usage + ")");
    std::vector<double> values(expected);
    for(std::size_t i = 0; i < expected; ++i)
      if(!parse_real(words[i], values[i]))
        fail("expected a finite number, got '" + words[i] + "' (usage: " + usage + ")");
    return values;
  }

  Deformation_constraints finish()
  {
    const std::size_t n = m_positions.size();
    bool has_roi_statement = false;
    for(std::size_t v = 0; v < n && !has_roi_statement; ++v)
      has_roi_statement = m_roi_line[v] != 0;
    if(!has_roi_statement)
      fail_file("no 'roi' statement: the region of interest is not defined");
    if(!m_has_handle_statement)
      fail_file("no 'handle' statement: nothing would move");

    Deformation_constraints result;
    result.in_roi.assign(n, 0);
    result.is_handle.assign(n, 0);
    result.targets.assign(n, Eigen::Vector3d::Zero());
    for(std::size_t v = 0; v < n; ++v)
    {
      if(m_handle_line[v] != 0 && m_fixed_line[v] != 0)
        fail_at(std::max(m_handle_line[v], m_fixed_line[v]),
                "vertex " + std::to_string(v) + " is both a handle (line " +
                    std::to_string(m_handle_line[v]) + ") and fixed (line " +
                    std::to_string(m_fixed_line[v]) + ")");
      if(m_target_line[v] != 0 && m_handle_line[v] == 0)
        fail_at(m_target_line[v], "vertex " + std::to_string(v) +
                                      " has a target but is not a handle vertex");
      result.is_handle[v] = (m_handle_line[v] != 0);
      result.in_roi[v] = result.is_handle[v] || (m_roi_line[v] != 0 && m_fixed_line[v] == 0);
      if(result.is_handle[v])
        result.targets[v] = (m_target_line[v] != 0) ? m_explicit_target[v] : m_motion * m_positions[v];
    }
    return result;
  }

  [[noreturn]] void fail(const std::string& message) const { fail_at(m_line_number, message); }

  [[noreturn]] void fail_at(std::size_t line, const std::string& message) const
  {
    throw Constraint_error(m_name + ":" + std::to_string(line) + ": " + message);
  }

  [[noreturn]] void fail_file(const std::string& message) const
  {
    throw Constraint_error(m_name + ": " + message);
  }

  const std::string m_name;
  const std::vector<Eigen::Vector3d>& m_positions;
  std::size_t m_line_number = 0;
  // Per vertex: the first line that selected it, 0 if none.
  std::vector<std::size_t> m_roi_line, m_fixed_line, m_handle_line, m_target_line;
  std::vector<Eigen::Vector3d> m_explicit_target;
  bool m_has_handle_statement = false;
  Eigen::Affine3d m_motion; // composition of the translate and rotate statements
};

} // namespace internal

/// Reads a plain-text constraint file for a mesh whose vertex `i` is at
/// `positions[i]`. Statements, one per line, `#` starts a comment:
///
///     roi    <selection>     vertices of the region of interest (lines add up)
///     fixed  <selection>     removed from the region of interest: never move
///     handle <selection>     control vertices (always in the region of interest)
///     translate x y z        moves the handle targets
///     rotate ax ay az angle_degrees cx cy cz
///                            rotates the handle targets about the axis through c
///     target id x y z        explicit target of one handle vertex
///
/// where a selection is `all`, `box xmin ymin zmin xmax ymax zmax`,
/// `sphere cx cy cz radius` or a list of vertex ids and inclusive ranges
/// `a-b`. Translations and rotations compose in file order and move every
/// handle vertex from its rest position; `target` overrides the result for
/// one vertex. Throws `Constraint_error` with the line number.
inline Deformation_constraints read_constraint_file(const std::string& filename,
                                                    const std::vector<Eigen::Vector3d>& positions)
{
  std::ifstream is(filename);
  if(!is)
    throw Constraint_error("cannot open the constraint file " + filename);
  internal::Constraint_file_reader reader(filename, positions);
  return reader.read(is);
}

/// Reads a `.sel` file and a `.def` file (Botsch and Sorkine 2008) for a mesh
/// whose vertex `i` is at `positions[i]`. Throws `Constraint_error`.
inline Deformation_constraints read_selection_files(const std::string& selection_file,
                                                    const std::string& transformation_file,
                                                    const std::vector<Eigen::Vector3d>& positions)
{
  std::vector<CGAL::IO::Deformation_vertex_status> status;
  Eigen::Matrix4d transformation;
  try
  {
    status = CGAL::IO::read_selection(selection_file, positions.size());
  }
  catch(const CGAL::Spectral_deformation_error& e)
  {
    throw Constraint_error(selection_file + ": " + e.what());
  }
  try
  {
    transformation = CGAL::IO::read_handle_transformation(transformation_file);
  }
  catch(const CGAL::Spectral_deformation_error& e)
  {
    throw Constraint_error(transformation_file + ": " + e.what());
  }
  const std::size_t n = positions.size();
  Deformation_constraints result;
  result.in_roi.assign(n, 0);
  result.is_handle.assign(n, 0);
  result.targets.assign(n, Eigen::Vector3d::Zero());
  for(std::size_t v = 0; v < n; ++v)
  {
    result.in_roi[v] = (status[v] != CGAL::IO::FIXED_VERTEX);
    result.is_handle[v] = (status[v] == CGAL::IO::HANDLE_VERTEX);
    if(result.is_handle[v])
      result.targets[v] = (transformation * positions[v].homogeneous()).head<3>();
  }
  if(result.number_of_handle_vertices() == 0)
    throw Constraint_error(selection_file + ": no handle vertex (status 2): nothing would move");
  return result;
}

} // namespace Deformation_tool

#endif // SSMD_TOOLS_DEFORMATION_CONSTRAINTS_H
