// Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The options of the command-line tool ssmd_deform and its help text.

#ifndef SSMD_TOOLS_COMMAND_LINE_OPTIONS_H
#define SSMD_TOOLS_COMMAND_LINE_OPTIONS_H

#include "Deformation_constraints.h" // parse_real, parse_index

#include <cstddef>
#include <stdexcept>
#include <string>
#include <vector>

namespace Deformation_tool {

/// An invalid command line; the program prints the message and a hint to
/// `--help`, and exits with status 2.
class Usage_error : public std::runtime_error
{
public:
  explicit Usage_error(const std::string& what) : std::runtime_error(what) {}
};

enum class Algorithm { SPECTRAL, LINEAR, SPATIAL };
enum class Policy { EXACT, SOFT };

struct Command_line_options
{
  std::string mesh_file;
  std::string constraint_file;      // the plain-text format, or
  std::string selection_file;       // a .sel file and
  std::string transformation_file;  // a .def file
  std::string output_file;          // empty: <mesh without extension>_deformed.<extension>
  std::string basis_cache_file;     // empty: <mesh>.ssmd-basis-m<m>
  Algorithm algorithm = Algorithm::SPECTRAL;
  Policy policy = Policy::EXACT;
  std::size_t frequencies = 100;
  unsigned int iterations = 10;
  double tolerance = 1e-4;
  double constraint_weight = 1.0;
  bool use_cache = true;
  bool render = false;
  bool quiet = false;
  bool help = false;
  bool version = false;
};

inline const char* help_text()
{
  return R"(Usage: ssmd_deform [options] MESH CONSTRAINTS
       ssmd_deform [options] MESH SELECTION.sel TRANSFORMATION.def

Deforms a triangle mesh with spectral dual Laplacian editing (Spectral Surface
Deformation with Dual Mesh) and writes the result.

MESH is any file that CGAL::IO::read_polygon_mesh reads into a Surface_mesh
(.off, .obj, .ply, .stl, .ts, .vtp when CGAL has VTK). It must be a triangle
mesh. Vertex ids are 0-based, in the order of the vertices of the mesh as read
(for OFF, OBJ and PLY files: the order of the file).

Options:
  -o, --output PATH       where to write the result; the format follows the
                          extension (.off, .obj, .ply, .stl, .ts). Default:
                          MESH without its extension + "_deformed" + extension.
                          The file is written only when everything succeeded.
  --algorithm NAME        spectral (default): the paper's iterated spectral dual
                          Laplacian editing; linear: the same reduced system
                          solved once, without following rotations; spatial: dual
                          Laplacian editing on the full-resolution region (no
                          basis, slower to prepare on large regions).
  --frequencies M         number of manifold harmonics of the basis (default 100;
                          a region with fewer vertices uses all of them).
  --iterations N          maximal number of solves of the iteration (default 10,
                          at least 1).
  --tolerance T           stop when the relative step falls below T (default
                          1e-4; 0 runs all iterations).
  --weight W              constraint weight of the reduced system (default 1).
  --policy NAME           exact (default): handles land exactly on their targets;
                          soft: the paper's least-squares constraints.
  --basis-cache PATH      file that stores the basis between runs. Default: next
                          to the mesh, MESH.ssmd-basis-mM (M = --frequencies). A
                          cache that belongs to another mesh, another region of
                          interest or another geometry, or that is corrupted, is
                          detected, ignored with a warning and rewritten.
  --no-cache              neither read nor write a basis cache.
  --render                also write OUTPUT_before.png and OUTPUT_after.png
                          (OUTPUT without extension), rendered with the same
                          camera by f3d under xvfb-run (both must be installed).
  -q, --quiet             print only warnings and errors.
  -h, --help              print this help and exit.
  --version               print the version and exit.

Constraints, format 1: a .sel and a .def file (Botsch and Sorkine 2008).
  The .sel file holds one status per vertex, in vertex order: 0 fixed (outside
  the region of interest), 1 region of interest, 2 handle. The .def file holds
  a 4x4 row-major matrix (last row 0 0 0 1) that moves the handle vertices.
  '#' starts a comment in both.

Constraints, format 2: a text file, one statement per line, '#' starts a
comment:
  roi SELECTION           add vertices to the region of interest (required)
  fixed SELECTION         remove vertices from it: they never move
  handle SELECTION        control vertices (required; always in the region)
  translate X Y Z         move the handle targets by (X, Y, Z)
  rotate AX AY AZ DEGREES CX CY CZ
                          rotate the handle targets by DEGREES about the axis
                          (AX, AY, AZ) through the point (CX, CY, CZ)
  target ID X Y Z         explicit target of one handle vertex
  where SELECTION is one of
    all                                   every vertex
    box XMIN YMIN ZMIN XMAX YMAX ZMAX     the vertices in an axis-aligned box
    sphere CX CY CZ RADIUS                the vertices in a ball
    ID ID-ID ...                          vertex ids and inclusive id ranges
  Statements of the same kind add up. translate and rotate compose in file
  order and move every handle vertex from its rest position; a target
  statement replaces the result for its vertex. A selection that selects no
  vertex, an id out of range, a handle that is also fixed, a target of a
  vertex that is not a handle, or any malformed line is an error that names
  the line. Example (bend the top of a mesh by 45 degrees about the x axis):
    roi all
    fixed box -1e9 -1e9 -1e9  1e9 0.2 1e9     # the bottom stays
    handle box -1e9 0.9 -1e9  1e9 1e9 1e9     # the top is moved
    rotate 1 0 0  45  0 0.9 0

Output: a progress bar while the basis is computed (on a terminal), then a
report: the timing of every phase, the iterations, and the largest distance of
a handle vertex to its target relative to the bounding-box diagonal of the
mesh.

Exit status: 0 on success, 1 when an input cannot be read or the deformation
fails (nothing is written then), 2 on an invalid command line.
)";
}

namespace internal {

inline std::size_t parse_count(const std::string& option, const std::string& value,
                               std::size_t minimum)
{
  std::size_t result = 0;
  if(!parse_index(value, result) || result < minimum)
    throw Usage_error(option + " expects an integer of at least " + std::to_string(minimum) +
                      ", got '" + value + "'");
  return result;
}

inline double parse_non_negative(const std::string& option, const std::string& value,
                                 bool allow_zero)
{
  double result = 0;
  if(!parse_real(value, result) || result < 0 || (!allow_zero && result == 0))
    throw Usage_error(option + " expects a " + (allow_zero ? "non-negative" : "positive") +
                      " finite number, got '" + value + "'");
  return result;
}

} // namespace internal

/// Parses the command line; throws `Usage_error`.
inline Command_line_options parse_command_line(int argc, const char* const* argv)
{
  Command_line_options options;
  std::vector<std::string> positional;
  bool only_positional = false;
  for(int i = 1; i < argc; ++i)
  {
    std::string word = argv[i];
    if(only_positional || word.empty() || word[0] != '-' || word == "-")
    {
      positional.push_back(word);
      continue;
    }
    if(word == "--")
    {
      only_positional = true;
      continue;
    }
    // --name=value or --name value
    std::string value;
    bool has_inline_value = false;
    const std::size_t equal = word.find('=');
    if(word.compare(0, 2, "--") == 0 && equal != std::string::npos)
    {
      value = word.substr(equal + 1);
      word = word.substr(0, equal);
      has_inline_value = true;
    }
    auto takes_no_value = [&]() {
      if(has_inline_value)
        throw Usage_error(word + " takes no value");
    };
    auto next_value = [&]() -> std::string {
      if(has_inline_value)
        return value;
      if(i + 1 >= argc)
        throw Usage_error(word + " expects a value");
      return argv[++i];
    };

    if(word == "-h" || word == "--help")
    {
      takes_no_value();
      options.help = true;
    }
    else if(word == "--version")
    {
      takes_no_value();
      options.version = true;
    }
    else if(word == "-q" || word == "--quiet")
    {
      takes_no_value();
      options.quiet = true;
    }
    else if(word == "--render")
    {
      takes_no_value();
      options.render = true;
    }
    else if(word == "--no-cache")
    {
      takes_no_value();
      options.use_cache = false;
    }
    else if(word == "-o" || word == "--output")
    {
      options.output_file = next_value();
      if(options.output_file.empty())
        throw Usage_error(word + " expects a file name");
    }
    else if(word == "--basis-cache")
    {
      options.basis_cache_file = next_value();
      if(options.basis_cache_file.empty())
        throw Usage_error(word + " expects a file name");
    }
    else if(word == "--algorithm")
    {
      const std::string name = next_value();
      if(name == "spectral")
        options.algorithm = Algorithm::SPECTRAL;
      else if(name == "linear")
        options.algorithm = Algorithm::LINEAR;
      else if(name == "spatial")
        options.algorithm = Algorithm::SPATIAL;
      else
        throw Usage_error("--algorithm expects spectral, linear or spatial, got '" + name + "'");
    }
    else if(word == "--policy")
    {
      const std::string name = next_value();
      if(name == "exact")
        options.policy = Policy::EXACT;
      else if(name == "soft")
        options.policy = Policy::SOFT;
      else
        throw Usage_error("--policy expects exact or soft, got '" + name + "'");
    }
    else if(word == "--frequencies")
      options.frequencies = internal::parse_count(word, next_value(), 1);
    else if(word == "--iterations")
    {
      const std::size_t iterations = internal::parse_count(word, next_value(), 1);
      if(iterations > 100000)
        throw Usage_error("--iterations expects at most 100000, got " + std::to_string(iterations));
      options.iterations = static_cast<unsigned int>(iterations);
    }
    else if(word == "--tolerance")
      options.tolerance = internal::parse_non_negative(word, next_value(), true);
    else if(word == "--weight")
      options.constraint_weight = internal::parse_non_negative(word, next_value(), false);
    else
      throw Usage_error("unknown option '" + word + "'");
  }
  if(options.help || options.version)
    return options;

  if(positional.size() == 2)
  {
    options.mesh_file = positional[0];
    options.constraint_file = positional[1];
  }
  else if(positional.size() == 3)
  {
    options.mesh_file = positional[0];
    options.selection_file = positional[1];
    options.transformation_file = positional[2];
  }
  else
    throw Usage_error(positional.empty()
                          ? std::string("missing the mesh and the constraints")
                          : "expected MESH CONSTRAINTS or MESH SELECTION.sel TRANSFORMATION.def, got " +
                                std::to_string(positional.size()) + " file name" +
                                (positional.size() == 1 ? "" : "s"));
  if(options.use_cache == false && !options.basis_cache_file.empty())
    throw Usage_error("--no-cache and --basis-cache exclude each other");
  return options;
}

} // namespace Deformation_tool

#endif // SSMD_TOOLS_COMMAND_LINE_OPTIONS_H
