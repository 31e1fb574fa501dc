// Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The options of the command-line tool ssmd_deform and its help text, on
// CLI11 (Debian package libcli11-dev).

#ifndef SSMD_TOOLS_COMMAND_LINE_OPTIONS_H
#define SSMD_TOOLS_COMMAND_LINE_OPTIONS_H

#include "Deformation_constraints.h" // parse_real, parse_index

#include <CLI/CLI.hpp>

#include <cstddef>
#include <memory>
#include <sstream>
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
enum class Energy { DUAL_LAPLACIAN, ARAP, DUAL_LAPLACIAN_AND_ARAP };

struct Command_line_options
{
  std::string mesh_file;
  std::string constraint_file;      // the plain-text format, or
  std::string selection_file;       // a .sel file and
  std::string transformation_file;  // a .def file
  std::string output_file;          // empty: <mesh without extension>_deformed.<extension>
  std::string basis_cache_file;     // empty: a file of the user's cache folder
  Algorithm algorithm = Algorithm::SPECTRAL;
  Policy policy = Policy::EXACT;
  Energy energy = Energy::DUAL_LAPLACIAN_AND_ARAP;
  bool approximate_basis = true; // CGAL::Partition_of_unity_eigensolver_traits; false: block Lanczos
  std::size_t frequencies = 100;
  long long rotation_patches = -1; // negative: the library's default
  long long single_precision_threshold = -1; // negative: the library's default
  double stage_angle = -1;         // degrees; negative: the library's default
  bool volume_preservation = false; // the detail transfer keeps the enclosed volume
  unsigned int iterations = 10;
  double tolerance = 1e-4;
  double refine_tolerance = -1;           // negative: no refinement after the deformation
  unsigned int refine_iterations = 1000;  // the cap of the refinement
  double constraint_weight = 1.0;
  bool use_cache = true;
  bool render = false;
  bool quiet = false;
  bool help = false;
  bool version = false;
  std::string help_text; // filled when `help` is set
};

namespace internal {

inline const char* description_text()
{
  return R"(Deforms a triangle mesh with spectral dual Laplacian editing (Spectral Surface
Deformation with Dual Mesh) and writes the result.

MESH is any file that CGAL::IO::read_polygon_mesh reads into a Surface_mesh
(.off, .obj, .ply, .stl, .ts, .vtp when CGAL has VTK). It must be a triangle
mesh. Vertex ids are 0-based, in the order of the vertices of the mesh as read
(for OFF, OBJ and PLY files: the order of the file).)";
}

inline const char* footer_text()
{
  return R"(Constraints, format 1: a .sel and a .def file (Botsch and Sorkine 2008).
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

Basis cache: the basis of the region of interest, the expensive part of the
preparation, is kept between runs in $XDG_CACHE_HOME/ssmd/ (by default
~/.cache/ssmd/), in a file named after a hash of the mesh file, of the region
of interest and of the number of frequencies; a second run on the same mesh
and region, with other handles or targets, skips the eigensolve. Delete the
folder to reclaim the space.

Output: while the basis is computed, a progress bar that fits the terminal on
standard error, or, when standard error is not a terminal (a pipe, a log
file), a line every tenth of the work or every few seconds. Then a report on
standard output: the timing of every phase, the iterations, and the largest
distance of a handle vertex to its target relative to the bounding-box
diagonal of the mesh.

Exit status: 0 on success, 1 when an input cannot be read or the deformation
fails (nothing is written then), 2 on an invalid command line.
)";
}

// Breaks `text` into lines of at most `width` characters at spaces; the
// line breaks of `text` are kept.
inline std::string wrap(const std::string& text, std::size_t width)
{
  std::string result, line;
  std::istringstream paragraphs(text);
  std::string paragraph;
  bool first_paragraph = true;
  while(std::getline(paragraphs, paragraph))
  {
    if(!first_paragraph)
      result += '\n';
    first_paragraph = false;
    std::istringstream words(paragraph);
    std::string word;
    line.clear();
    while(words >> word)
    {
      if(!line.empty() && line.size() + 1 + word.size() > width)
      {
        result += line + '\n';
        line.clear();
      }
      line += (line.empty() ? "" : " ") + word;
    }
    result += line;
  }
  return result;
}

// The layout of `--help`: the usage lines first, option names as
// "-o, --output PATH", and descriptions wrapped to fit 80 columns. CLI11's
// own notes (defaults, exclusions) are left out: the descriptions say them
// in words.
class Help_formatter : public CLI::Formatter
{
public:
  static constexpr std::size_t name_width = 26;
  // One column short of 80: a character in the last column makes some
  // terminals wrap.
  static constexpr std::size_t line_width = 79;

  Help_formatter() { column_width(name_width); }

  std::string make_help(const CLI::App* app, std::string name, CLI::AppFormatMode mode) const override
  {
    if(mode == CLI::AppFormatMode::Sub)
      return CLI::Formatter::make_help(app, name, mode);
    std::ostringstream out;
    out << make_usage(app, name) << '\n'
        << make_description(app) << make_groups(app, mode) << '\n'
        << app->get_footer();
    return out.str();
  }

  std::string make_usage(const CLI::App*, std::string name) const override
  {
    return "Usage: " + name + " [options] MESH CONSTRAINTS\n       " + name +
           " [options] MESH SELECTION.sel TRANSFORMATION.def\n";
  }

  std::string make_option_name(const CLI::Option* option, bool positional) const override
  {
    std::string names = CLI::Formatter::make_option_name(option, positional);
    std::string result;
    for(char c : names)
      result += (c == ',') ? std::string(", ") : std::string(1, c);
    return result;
  }

  std::string make_option_opts(const CLI::Option* option) const override
  {
    return option->get_option_text().empty() ? std::string() : " " + option->get_option_text();
  }

  std::string make_option_desc(const CLI::Option* option) const override
  {
    return wrap(option->get_description(), line_width - name_width);
  }
};

// A CLI11 check with the tool's own message: "OPTION expects WHAT, got
// 'VALUE'". It throws instead of returning the message because CLI11 would
// prefix the message with "OPTION: ", and the tool's messages read as a
// sentence.
template <class Accepts>
CLI::Validator expects(const std::string& option, const std::string& what, Accepts accepts)
{
  return CLI::Validator(
      [option, what, accepts](std::string& value) -> std::string {
        if(!accepts(value))
          throw Usage_error(option + " expects " + what + ", got '" + value + "'");
        return std::string();
      },
      "");
}

inline bool is_count_at_least(const std::string& value, std::size_t minimum, std::size_t maximum)
{
  std::size_t result = 0;
  return parse_index(value, result) && result >= minimum && result <= maximum;
}

inline bool is_non_negative(const std::string& value, bool allow_zero)
{
  double result = 0;
  return parse_real(value, result) && result >= 0 && (allow_zero || result > 0);
}

// The option CLI11 names at the start of a message ("--iterations: ...",
// or "render was given ..." for a flag), for the messages the tool
// rephrases.
inline std::string leading_option(const std::string& message)
{
  std::string name = message.substr(0, message.find_first_of(": "));
  name.erase(0, name.find_first_not_of('-'));
  if(name.empty())
    return name;
  return (name.size() == 1 ? "-" : "--") + name;
}

} // namespace internal

/// Parses the command line; throws `Usage_error`. `--help` sets `help` and
/// `help_text`, `--version` sets `version`; the other fields are then not
/// checked.
inline Command_line_options parse_command_line(int argc, const char* const* argv)
{
  Command_line_options options;
  std::vector<std::string> files;
  std::string algorithm = "spectral", policy = "exact", energy = "dual-laplacian-and-arap", basis = "approximate";

  CLI::App app(internal::description_text(), "ssmd_deform");
  app.formatter(std::make_shared<internal::Help_formatter>());
  // Unknown options are reported by the tool (see below), in its own words.
  app.allow_extras();
  // As with most command-line tools, the last occurrence of an option wins.
  app.option_defaults()->multi_option_policy(CLI::MultiOptionPolicy::TakeLast);
  const auto not_empty = [](const std::string& value) { return !value.empty(); };
  app.add_option("-o,--output", options.output_file,
                 "where to write the result; the format follows the extension (.off, .obj, .ply, "
                 ".stl, .ts). Default: MESH without its extension + \"_deformed\" + extension. The "
                 "file is written only when everything succeeded.")
      ->option_text("PATH")
      ->check(internal::expects("--output", "a file name", not_empty));
  app.add_option("--algorithm", algorithm,
                 "spectral (default): the paper's iterated spectral dual Laplacian editing; linear: "
                 "the same reduced system solved once, without following rotations; spatial: dual "
                 "Laplacian editing on the full-resolution region (no basis, slower to prepare on "
                 "large regions).")
      ->option_text("NAME")
      ->check(internal::expects("--algorithm", "spectral, linear or spatial", [](const std::string& v) {
        return v == "spectral" || v == "linear" || v == "spatial";
      }));
  app.add_option("--frequencies", options.frequencies,
                 "number of manifold harmonics of the basis (default 100; a region with fewer "
                 "vertices uses all of them).")
      ->option_text("M")
      ->check(internal::expects("--frequencies", "an integer of at least 1", [](const std::string& v) {
        return internal::is_count_at_least(v, 1, static_cast<std::size_t>(-1));
      }));
  app.add_option("--rotation-patches", options.rotation_patches,
                 "rotation patches of the iteration (default: the library's, 1000; 0: one rotation "
                 "per dual vertex, the full iteration).")
      ->option_text("K")
      ->check(internal::expects("--rotation-patches", "an integer of at least 0", [](const std::string& v) {
        return internal::is_count_at_least(v, 0, static_cast<std::size_t>(-1));
      }));
  app.add_option("--single-precision-threshold", options.single_precision_threshold,
                 "the number of region vertices from which the basis is kept in float, half the "
                 "memory (default: the library's, 20000; 0: always).")
      ->option_text("N")
      ->check(internal::expects("--single-precision-threshold", "an integer of at least 0",
                                [](const std::string& v) {
        return internal::is_count_at_least(v, 0, static_cast<std::size_t>(-1));
      }));
  app.add_option("--stage-angle", options.stage_angle,
                 "the largest turn of a handle per stage of the spectral iteration, in degrees "
                 "(default: the library's, 30, with which large bends do not fold; 0: the targets "
                 "in one stage).")
      ->option_text("DEGREES")
      ->check(internal::expects("--stage-angle", "a non-negative finite number",
                                [](const std::string& v) { return internal::is_non_negative(v, true); }));
  app.add_flag("--volume-preservation", options.volume_preservation,
               "the spectral detail transfer keeps the volume the surface encloses (when the "
               "region is cut out of a closed surface).");
  app.add_option("--energy", energy,
                 "what the spectral iteration minimizes: dual-laplacian-and-arap (default, the sum "
                 "of the two), dual-laplacian (the paper's dual Laplacian editing: open sheets "
                 "bend with the least stretch) or arap (the as-rigid-as-possible energy of the "
                 "smooth mesh).")
      ->option_text("NAME")
      ->check(internal::expects("--energy", "dual-laplacian, arap or dual-laplacian-and-arap",
                                [](const std::string& v) {
        return v == "dual-laplacian" || v == "arap" || v == "dual-laplacian-and-arap";
      }));
  app.add_option("--basis", basis,
                 "how the basis of the spectral algorithms is computed: approximate (default; "
                 "eigenvectors approximated in a space of functions around sampled vertices, "
                 "several times faster on large meshes and exact on small ones) or exact (the "
                 "eigenvectors, by block Lanczos).")
      ->option_text("NAME")
      ->check(internal::expects("--basis", "exact or approximate",
                                [](const std::string& v) { return v == "exact" || v == "approximate"; }));
  app.add_option("--iterations", options.iterations,
                 "maximal number of solves of the iteration (default 10, at least 1).")
      ->option_text("N")
      ->check(internal::expects("--iterations", "an integer from 1 to 100000", [](const std::string& v) {
        return internal::is_count_at_least(v, 1, 100000);
      }));
  app.add_option("--tolerance", options.tolerance,
                 "stop when the relative step falls below T (default 1e-4; 0 runs all iterations).")
      ->option_text("T")
      ->check(internal::expects("--tolerance", "a non-negative finite number",
                                [](const std::string& v) { return internal::is_non_negative(v, true); }));
  app.add_option("--refine", options.refine_tolerance,
                 "after the deformation, refine it towards the optimum of the as-rigid-as-possible "
                 "energy until an iteration lowers the energy by less than T times its value "
                 "(e.g. 1e-5; 0 runs all --refine-iterations).")
      ->option_text("T")
      ->check(internal::expects("--refine", "a non-negative finite number",
                                [](const std::string& v) { return internal::is_non_negative(v, true); }));
  app.add_option("--refine-iterations", options.refine_iterations,
                 "maximal number of iterations of --refine (default 1000).")
      ->option_text("N")
      ->check(internal::expects("--refine-iterations", "an integer from 1 to 100000", [](const std::string& v) {
        return internal::is_count_at_least(v, 1, 100000);
      }));
  app.add_option("--weight", options.constraint_weight,
                 "constraint weight of the reduced system (default 1).")
      ->option_text("W")
      ->check(internal::expects("--weight", "a positive finite number",
                                [](const std::string& v) { return internal::is_non_negative(v, false); }));
  app.add_option("--policy", policy,
                 "exact (default): handles land exactly on their targets; soft: the paper's "
                 "least-squares constraints.")
      ->option_text("NAME")
      ->check(internal::expects("--policy", "exact or soft", [](const std::string& v) {
        return v == "exact" || v == "soft";
      }));
  CLI::Option* basis_cache =
      app.add_option("--basis-cache", options.basis_cache_file,
                     "file that stores the basis between runs, instead of the cache folder "
                     "($XDG_CACHE_HOME/ssmd/, by default ~/.cache/ssmd/). A cache that belongs to "
                     "another mesh, another region of interest or another geometry, or that is "
                     "corrupted, is detected, ignored with a warning and rewritten.")
          ->option_text("PATH")
          ->check(internal::expects("--basis-cache", "a file name", not_empty));
  bool no_cache = false;
  app.add_flag("--no-cache", no_cache, "neither read nor write a basis cache.")->excludes(basis_cache);
  app.add_flag("--render", options.render,
               "also write OUTPUT_before.png and OUTPUT_after.png (OUTPUT without extension), "
               "rendered with the same camera by f3d under xvfb-run (both must be installed).");
  app.add_flag("-q,--quiet", options.quiet,
               "print only warnings and errors: no progress and no report.");
  app.set_help_flag("-h,--help", "print this help and exit.");
  app.add_flag("--version", options.version, "print the version and exit.");
  app.add_option("files", files)->group("");
  app.footer(internal::footer_text());

  // Flags take no value: "--render=false" is refused rather than read.
  for(CLI::Option* option : app.get_options())
    if(option->get_expected_max() == 0)
      option->disable_flag_override();

  try
  {
    app.parse(argc, argv);
  }
  catch(const CLI::CallForHelp&)
  {
    options.help = true;
    options.help_text = app.help();
    return options;
  }
  catch(const CLI::ArgumentMismatch& e)
  {
    const std::string option = internal::leading_option(e.what());
    const std::string message = e.what();
    if(!option.empty() && message.find("flag override") != std::string::npos)
      throw Usage_error(option + " takes no value");
    if(!option.empty() && message.find("missing") != std::string::npos)
      throw Usage_error(option + " expects a value");
    throw Usage_error(message);
  }
  catch(const CLI::ExcludesError&)
  {
    throw Usage_error("--no-cache and --basis-cache exclude each other");
  }
  catch(const CLI::ParseError& e)
  {
    throw Usage_error(e.what());
  }
  if(options.version)
    return options;

  // Whatever CLI11 did not recognize: an unknown option, or, after "--",
  // a file name.
  for(const std::string& word : app.remaining())
    if(word.size() > 1 && word[0] == '-')
      throw Usage_error("unknown option '" + word.substr(0, word.find('=')) + "'");
  const std::vector<std::string> remaining = app.remaining();
  files.insert(files.end(), remaining.begin(), remaining.end());

  options.algorithm = algorithm == "linear"    ? Algorithm::LINEAR
                      : algorithm == "spatial" ? Algorithm::SPATIAL
                                               : Algorithm::SPECTRAL;
  options.policy = policy == "soft" ? Policy::SOFT : Policy::EXACT;
  options.energy = energy == "arap"             ? Energy::ARAP
                   : energy == "dual-laplacian" ? Energy::DUAL_LAPLACIAN
                                                : Energy::DUAL_LAPLACIAN_AND_ARAP;
  options.approximate_basis = (basis == "approximate");
  options.use_cache = !no_cache;

  if(files.size() == 2)
  {
    options.mesh_file = files[0];
    options.constraint_file = files[1];
  }
  else if(files.size() == 3)
  {
    options.mesh_file = files[0];
    options.selection_file = files[1];
    options.transformation_file = files[2];
  }
  else
    throw Usage_error(files.empty()
                          ? std::string("missing the mesh and the constraints")
                          : "expected MESH CONSTRAINTS or MESH SELECTION.sel TRANSFORMATION.def, got " +
                                std::to_string(files.size()) + " file name" +
                                (files.size() == 1 ? "" : "s"));
  return options;
}

} // namespace Deformation_tool

#endif // SSMD_TOOLS_COMMAND_LINE_OPTIONS_H
