// hitops: the Hi-TOPS part decomposition of a mesh file, or of a list of files, from the command line.
//
//   hitops INPUT [--labels OUT.seg] [--colored OUT.ply] [--primitives OUT.json]
//                [--primitive-mesh OUT.off] [--parts-glb OUT.glb [--parts-glb-primitives]]
//                [--labels-glb OUT.glb] [--thumbnail OUT.png] [--threads N] [parameter options]
//   hitops --batch LIST --out DIR [--shard I/N] [--mesh-timeout SECONDS] [--report] [--quiet]
//                [--threads N] [parameter options]
//
// `hitops --help` lists every option. A bad input gives a one-line error on stderr and exit
// status 1; output files are written to a temporary name and renamed once complete, so a failed
// run never leaves a partial file. In batch mode, the summary gives the SHA-256 of every input
// file, and `--mesh-timeout` decomposes each mesh in a child process that is killed when it takes
// longer (status `timeout`; the batch goes on with the next mesh, and the mesh leaves no output).
// On a terminal, a batch keeps a status line up to date (elsewhere: one line per mesh), and one
// mesh that takes over a second shows its stage; `--quiet` leaves only the errors. `--report`
// writes DIR/report.html, a contact sheet with a thumbnail of every mesh and its parts.
//
// On a glTF input, --parts-glb keeps the input's materials, textures, UVs, normals and vertex
// colours in each part, and --labels-glb writes the input's scene unchanged with the part of every
// triangle as an EXT_mesh_features feature ID (another format: the mesh as one glTF primitive).

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Part_decomposition/IO/read_mesh.h>
#include <CGAL/Part_decomposition/IO/write_labels_gltf.h>
#include <CGAL/Part_decomposition/IO/write_parts_gltf.h>
#include <CGAL/Part_decomposition/decompose.h>

#include "decomposition_settings.h"
#include "part_palette.h"
#include "part_renderer.h"
#include "progress_line.h"
#include "sha256.h"

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/global_control.h>
#endif

#include <algorithm>
#include <array>
#include <cctype>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iomanip>
#include <iostream>
#include <map>
#include <memory>
#include <mutex>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include <poll.h>
#include <sys/wait.h>
#include <unistd.h>

namespace {

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
typedef CGAL::Part_decomposition::Superquadric<K> Superquadric;
namespace PD = CGAL::Part_decomposition;
namespace PDP = CGAL::Part_decomposition::parameters;

// A user error: one line on stderr, exit status 1.
struct Usage_error : std::runtime_error
{
  using std::runtime_error::runtime_error;
};

struct Options
{
  std::string input, labels, colored, primitives, primitive_mesh, hierarchy;
  std::string batch, out_dir;
  std::string parts_glb, labels_glb;
  bool parts_glb_primitives = false;
  std::size_t shard = 0, shards = 1;
  double mesh_timeout = 0.; // seconds per mesh of a batch; 0: no limit
  int threads = 0;
  bool timings = false;
  bool quiet = false, report = false;
  std::string thumbnail;
  int thumbnail_width = 320, thumbnail_height = 160;
  Part_decomposition_tools::Decomposition_settings decomposition; // the named parameters (of the reader too)
};

const char* const usage_text =
  "usage: hitops INPUT [--labels OUT.seg] [--colored OUT.ply] [--primitives OUT.json]\n"
  "                    [--primitive-mesh OUT.off] [--parts-glb OUT.glb [--parts-glb-primitives]]\n"
  "                    [--labels-glb OUT.glb] [--thumbnail OUT.png] [--threads N] [parameter options]\n"
  "       hitops --batch LIST --out DIR [--shard I/N] [--mesh-timeout SECONDS] [--report] [--quiet]\n"
  "                    [--threads N] [parameter options]\n"
  "\n"
  "Decomposes a triangle mesh (OFF, OBJ, PLY, STL, glTF .gltf/.glb) into parts with the Hi-TOPS method.\n"
  "\n"
  "outputs:\n"
  "  --labels FILE            one part id per line, one line per face of INPUT, in its order\n"
  "  --colored FILE           the mesh as PLY with one colour per part\n"
  "  --primitives FILE        the superquadric of each part as JSON, in INPUT's coordinates\n"
  "  --primitive-mesh FILE    the superquadrics as one triangle mesh (OFF)\n"
  "  --hierarchy FILE         the part hierarchy as JSON: per node its children, merge cost and\n"
  "                           superquadric; the leaf of each face of INPUT, in its order\n"
  "  --parts-glb FILE         the parts as binary glTF: one mesh and node part_K per part, its colour as\n"
  "                           material, to pick parts one by one in Blender or any glTF viewer\n"
  "                           (a glTF INPUT: each part keeps the input's materials, textures, UVs, normals,\n"
  "                           tangents and vertex colours, in the frame of the scene)\n"
  "  --parts-glb-primitives   with --parts-glb: also the superquadrics, nodes primitive_K (half transparent)\n"
  "  --labels-glb FILE        binary glTF with the part of every face as an EXT_mesh_features feature ID\n"
  "                           (vertex attribute _FEATURE_ID_0): a glTF INPUT's scene unchanged otherwise,\n"
  "                           another format as one mesh\n"
  "  --thumbnail FILE         a PNG picture: the input in grey beside its parts in their colours\n"
  "  --thumbnail-size WxH     pixels of the thumbnails of --thumbnail and --report (default 320x160)\n"
  "  --quiet                  no progress on stderr, only errors (on a terminal, a batch keeps a status\n"
  "                           line and one mesh that takes over a second shows its stage; elsewhere a\n"
  "                           batch prints one line per mesh)\n"
  "  --timings                print the time of each stage on stderr\n"
  "  --threads N              number of threads (default: all cores)\n"
  "  --list-parameters        the table of the parameters (name, option, default, paper, type, range, stage,\n"
  "                           kind, meaning) as tab-separated values\n"
  "batch processing:\n"
  "  --batch LIST             a file with one mesh path per line (# starts a comment)\n"
  "  --out DIR                (created if needed) writes DIR/NAME.seg and DIR/NAME.json per mesh and a summary\n"
  "                           DIR/summary[.I-of-N].tsv (name, input, status, faces, parts, seconds, sha256 of\n"
  "                           the input, message); meshes whose outputs exist are skipped\n"
  "  --shard I/N              process only the meshes of rank I modulo N (0 <= I < N)\n"
  "  --mesh-timeout SECONDS   stop a mesh (read, decomposition, outputs) that takes longer: status timeout, no\n"
  "                           output, the batch goes on (each mesh then runs in a child process); 0: no limit\n"
  "  --report                 also writes DIR/thumbnails/NAME.png per mesh and DIR/report[.I-of-N].html, a\n"
  "                           contact sheet (no script, opens offline): thumbnail, faces, parts, seconds,\n"
  "                           status and message of every mesh, links to its outputs\n";

// Former spellings of parameter options, still accepted: the option, its parameter and the value it
// implies (nullptr: it takes one).
struct Alias
{
  const char* option;
  const char* parameter;
  const char* value;
};
const Alias aliases[] = {
  {"--no-pieces", "method_variant", "use_pieces=false"}, {"--min-part-area", "minimum_part_area", nullptr},
  {"--resolutions", "voxel_resolutions", nullptr}, {"--samples-per-face", "number_of_points_per_face", nullptr},
  {"--neighbors", "number_of_neighbors", nullptr}, {"--no-density", "method_variant", "use_density=false"},
  {"--margin", "normalization_margin", nullptr},
  {"--truncation", "tsdf_truncation", nullptr}, {"--sign-method", "tsdf_sign_method", nullptr},
  {"--flow-tolerance", "flow_zone_tolerance", nullptr}, {"--min-body-volume", "minimum_body_volume", nullptr},
  {"--min-surface-volume", "minimum_surface_volume", nullptr}, {"--coverage", "coverage_target", nullptr},
  {"--max-primitives", "maximum_number_of_primitives", nullptr},
  {"--no-freeze", "method_variant", "use_freeze_zone=false"}, {"--no-tsdf", "method_variant", "use_tsdf_guidance=false"},
  {"--no-body-seeds", "method_variant", "use_body_seeds=false"}, {"--no-exterior-band", "method_variant", "use_exterior_band_samples=false"},
  {"--no-reachable-regions", "method_variant", "use_reachable_regions=false"}, {"--no-seed-exclusion", "method_variant", "use_seed_exclusion=false"},
  {"--max-solver-evaluations", "maximum_solver_evaluations", nullptr},
  {"--max-rejections-in-a-row", "maximum_rejections_in_a_row", nullptr},
  {"--no-primitive-merge", "method_variant", "merge_primitives=false"}, {"--min-merge-iou", "minimum_merge_iou", nullptr},
  {"--dihedral-quantile", "dihedral_percentile", nullptr}, {"--min-patch-size", "minimum_patch_size", nullptr},
  {"--max-patch-size", "patch_split_size", nullptr}, {"--no-sheet-merge", "method_variant", "merge_thin_sheets=false"},
  {"--max-merge-cost", "maximum_merge_cost", nullptr}, {"--parts", "number_of_parts", nullptr}};

// The option of a parameter of PD::parameter_table: its name with '-' for '_'.
std::string option_of(const std::string& parameter)
{
  std::string option = "--" + parameter;
  std::replace(option.begin(), option.end(), '_', '-');
  return option;
}

// How one parameter option reads its value into the options, and prints the value.
struct Parameter_option
{
  const PD::Parameter_description* parameter;
  std::function<void(Options&, const std::string&)> set;
  std::function<std::string(const Options&)> get;
};

template <typename T>
Parameter_option member_option(const char* name, T Part_decomposition_tools::Decomposition_settings::*member)
{
  return {PD::internal::find_parameter(name),
          [member](Options& o, const std::string& text) { Part_decomposition_tools::parse_value(text, o.decomposition.*member); },
          [member](const Options& o) { return Part_decomposition_tools::format_value(o.decomposition.*member); }};
}

// Every parameter option by its option name; made from the settings, checked against the table.
const std::map<std::string, Parameter_option>& parameter_options()
{
  static const std::map<std::string, Parameter_option> table = [] {
    std::map<std::string, Parameter_option> t;
    Part_decomposition_tools::for_each_setting(
      [&](const char* name, auto member) { t.emplace(option_of(name), member_option(name, member)); });
    // a parameter of the table without option, or an option of no parameter, is a bug of this list
    for(const PD::Parameter_description& p : PD::parameter_table)
      if(p.kind == PD::Parameter_kind::VALUE && !t.count(option_of(p.name))) throw std::logic_error(std::string("no option for ") + p.name);
    for(const auto& o : t)
      if(o.second.parameter == nullptr) throw std::logic_error("no parameter for " + o.first);
    return t;
  }();
  return table;
}

// The title of a group of options.
const char* stage_title(PD::Parameter_stage stage)
{
  switch(stage)
  {
    case PD::Parameter_stage::READING: return "reading the mesh";
    case PD::Parameter_stage::PIECES: return "pieces (segment_pieces())";
    case PD::Parameter_stage::PRIOR: return "prior (compute_flow_freeze_prior())";
    case PD::Parameter_stage::DISTANCE_FIELD: return "distance field (compute_tsdf())";
    case PD::Parameter_stage::FITTING: return "fitting (fit_superquadrics())";
    case PD::Parameter_stage::OVER_SEGMENTATION: return "over-segmentation (over_segment())";
    case PD::Parameter_stage::ASSIGNMENT: return "assignment (assign_parts())";
    case PD::Parameter_stage::HIERARCHY: return "part hierarchy (decompose())";
    default: return "reports";
  }
}

// One line per parameter: option, default, meaning, range, former spellings.
// At most 110 columns: the text goes on under the meaning.
void print_wrapped(std::ostream& out, std::string line)
{
  const std::size_t width = 110, indent = 38;
  while(line.size() > width)
  {
    const std::size_t cut = line.rfind(' ', width);
    if(cut == std::string::npos || cut <= indent) break;
    out << line.substr(0, cut) << '\n';
    line = std::string(indent, ' ') + line.substr(cut + 1);
  }
  out << line << '\n';
}

void print_parameter(std::ostream& out, const PD::Parameter_description& p, const Options& defaults)
{
  const std::string option = option_of(p.name);
  std::string line = "  " + option + " " + parameter_options().at(option).get(defaults);
  line += std::string(line.size() < 38 ? 38 - line.size() : 2, ' ') + p.meaning;
  if(*p.range) line += std::string("; ") + p.range;
  std::string also;
  for(const Alias& a : aliases)
    if(p.name == std::string(a.parameter)) also += std::string(also.empty() ? "" : ", ") + a.option + (a.value ? std::string(" for ") + a.value : "");
  if(!also.empty()) line += " [also " + also + "]";
  print_wrapped(out, line);
}

// One line per switch of the method: SWITCH=DEFAULT, the paper's value, meaning.
void print_switch(std::ostream& out, const PD::Parameter_description& p)
{
  using Part_decomposition_tools::format_switch;
  std::string line = "  " + std::string(p.name) + "=" + format_switch(PD::Method_variant(), p.name);
  line += std::string(line.size() < 38 ? 38 - line.size() : 2, ' ') + "paper: " +
          format_switch(PD::Method_variant::paper_literal(), p.name) + "; " + p.meaning;
  print_wrapped(out, line);
}


// The usage text, then every parameter with an option, grouped by stage, the switches of the method last.
void print_help(std::ostream& out)
{
  const Options defaults;
  out << usage_text
      << "parameters, the named parameters of decompose() (defaults: the paper's, Table A.1, or the package's\n"
         "documented choices); booleans take true or false, lists are comma-separated, enumerations take\n"
         "their lower-case names:\n";
  for(int s = 0; s <= int(PD::Parameter_stage::OUTPUT); ++s)
  {
    bool title = false;
    for(const PD::Parameter_description& p : PD::parameter_table)
    {
      if(int(p.stage) != s || p.kind != PD::Parameter_kind::VALUE) continue;
      if(!title) out << " " << stage_title(p.stage) << ":\n";
      title = true;
      print_parameter(out, p, defaults);
    }
  }
  out << " the switches of --method-variant (each undoes a documented choice of the package, or reproduces the\n"
         " paper literally): SWITCH=VALUE, the package's default first, then the paper's:\n";
  for(const PD::Parameter_description& p : PD::parameter_table)
    if(p.kind == PD::Parameter_kind::METHOD_SWITCH) print_switch(out, p);
}

// The table as tab-separated values, for the manual's generator: name, option, default, paper
// (a switch's value in the paper), type, range, stage, kind, meaning; the default of an option is
// the value hitops passes.
void print_parameter_table(std::ostream& out)
{
  const Options defaults;
  static const char* const kinds[] = {"value", "object", "switch"};
  out << "name\toption\tdefault\tpaper\ttype\trange\tstage\tkind\tmeaning\n";
  for(const PD::Parameter_description& p : PD::parameter_table)
  {
    const bool value = p.kind == PD::Parameter_kind::VALUE, method_switch = p.kind == PD::Parameter_kind::METHOD_SWITCH;
    const std::string option = value ? option_of(p.name) : "";
    using Part_decomposition_tools::format_switch;
    out << p.name << '\t' << option << '\t'
        << (value ? parameter_options().at(option).get(defaults)
                  : method_switch ? format_switch(PD::Method_variant(), p.name) : std::string(p.default_value))
        << '\t' << (method_switch ? format_switch(PD::Method_variant::paper_literal(), p.name) : "") << '\t' << p.type << '\t' << p.range << '\t' << stage_title(p.stage) << '\t'
        << kinds[int(p.kind)] << '\t' << p.meaning << '\n';
  }
}

double to_number(const std::string& option, const std::string& text)
{
  std::istringstream in(text);
  double v;
  char extra;
  if(!(in >> v) || (in >> extra) || !std::isfinite(v))
    throw Usage_error("option " + option + " expects a number, got '" + text + "'");
  return v;
}

unsigned int to_count(const std::string& option, const std::string& text)
{
  const double v = to_number(option, text);
  if(v < 0 || v != std::floor(v) || v > 1e9)
    throw Usage_error("option " + option + " expects a non-negative integer, got '" + text + "'");
  return static_cast<unsigned int>(v);
}

// Reads the parameter option argv[i] (and its value) into `o`; false if it is none.
bool set_parameter(Options& o, const std::string& a, int argc, char** argv, int& i)
{
  std::string option = a;
  const char* implied = nullptr;
  for(const Alias& alias : aliases)
    if(a == alias.option)
    {
      option = option_of(alias.parameter);
      implied = alias.value;
    }
  const auto it = parameter_options().find(option);
  if(it == parameter_options().end()) return false;
  if(!implied && i + 1 >= argc) throw Usage_error("option " + a + " expects a value");
  const std::string text = implied ? implied : argv[++i];
  try
  {
    it->second.set(o, text);
  }
  catch(const std::invalid_argument& e)
  {
    throw Usage_error("option " + a + " expects " + e.what() + ", got '" + text + "'");
  }
  return true;
}

Options parse(int argc, char** argv)
{
  Options o;
  for(int i = 1; i < argc; ++i)
  {
    const std::string a = argv[i];
    auto value = [&]() -> std::string {
      if(i + 1 >= argc) throw Usage_error("option " + a + " expects a value");
      return argv[++i];
    };
    if(a == "--help" || a == "-h") { print_help(std::cout); std::exit(EXIT_SUCCESS); }
    else if(a == "--labels") o.labels = value();
    else if(a == "--colored") o.colored = value();
    else if(a == "--primitives") o.primitives = value();
    else if(a == "--primitive-mesh") o.primitive_mesh = value();
    else if(a == "--hierarchy") o.hierarchy = value();
    else if(a == "--parts-glb") o.parts_glb = value();
    else if(a == "--parts-glb-primitives") o.parts_glb_primitives = true;
    else if(a == "--labels-glb") o.labels_glb = value();
    else if(a == "--threads") { o.threads = int(to_count(a, value())); if(o.threads < 1) throw Usage_error("--threads expects at least 1"); }
    else if(a == "--timings") o.timings = true;
    else if(a == "--quiet") o.quiet = true;
    else if(a == "--report") o.report = true;
    else if(a == "--thumbnail") o.thumbnail = value();
    else if(a == "--thumbnail-size")
    {
      const std::string s = value();
      const std::size_t x = s.find('x');
      if(x == std::string::npos) throw Usage_error("--thumbnail-size expects WxH");
      o.thumbnail_width = int(to_count(a, s.substr(0, x)));
      o.thumbnail_height = int(to_count(a, s.substr(x + 1)));
      if(o.thumbnail_width < 2 || o.thumbnail_height < 2 || o.thumbnail_width > 4096 || o.thumbnail_height > 4096)
        throw Usage_error("--thumbnail-size expects WxH, each from 2 to 4096");
    }
    else if(a == "--verbose")
    {
      // a flag before it took true or false: a value is read only if it is one
      const bool has_value = i + 1 < argc && (std::string(argv[i + 1]) == "true" || std::string(argv[i + 1]) == "false");
      o.decomposition.verbose = !has_value || std::string(argv[++i]) == "true";
    }
    else if(a == "--batch") o.batch = value();
    else if(a == "--mesh-timeout")
    {
      o.mesh_timeout = to_number(a, value());
      if(o.mesh_timeout < 0) throw Usage_error("--mesh-timeout expects a non-negative number of seconds");
    }
    else if(a == "--out") o.out_dir = value();
    else if(a == "--shard")
    {
      const std::string s = value();
      const std::size_t slash = s.find('/');
      if(slash == std::string::npos) throw Usage_error("--shard expects I/N");
      o.shard = to_count(a, s.substr(0, slash));
      o.shards = to_count(a, s.substr(slash + 1));
      if(o.shards < 1 || o.shard >= o.shards) throw Usage_error("--shard expects I/N with 0 <= I < N");
    }
    else if(a == "--list-parameters") { print_parameter_table(std::cout); std::exit(EXIT_SUCCESS); }
    else if(set_parameter(o, a, argc, argv, i)) {}
    else if(!a.empty() && a[0] == '-') throw Usage_error("unknown option " + a + " (see --help)");
    else if(o.input.empty()) o.input = a;
    else throw Usage_error("more than one input file: '" + o.input + "' and '" + a + "'");
  }
  if(o.batch.empty() && o.input.empty()) throw Usage_error("no input file (see --help)");
  if(!o.batch.empty() && !o.input.empty()) throw Usage_error("give either an input file or --batch, not both");
  if(!o.batch.empty() && o.out_dir.empty()) throw Usage_error("--batch needs --out DIR");
  if(o.parts_glb_primitives && o.parts_glb.empty()) throw Usage_error("--parts-glb-primitives needs --parts-glb FILE");
  if(o.mesh_timeout > 0 && o.batch.empty()) throw Usage_error("--mesh-timeout applies to --batch only");
  if(o.report && o.batch.empty()) throw Usage_error("--report applies to --batch only (one mesh: --thumbnail FILE)");
  if(!o.thumbnail.empty() && !o.batch.empty()) throw Usage_error("--thumbnail applies to one mesh (a batch: --report)");
  return o;
}

// Files written under a temporary name, renamed into place only when all of them are complete.
class Atomic_outputs
{
public:
  ~Atomic_outputs()
  {
    for(const auto& f : m_files) std::remove(f.second.c_str());
  }
  std::ofstream& open(const std::string& path)
  {
    const std::string tmp = path + ".tmp." + std::to_string(::getpid());
    m_files.emplace_back(path, tmp);
    m_streams.emplace_back(new std::ofstream(tmp, std::ios::binary));
    if(!*m_streams.back()) throw std::runtime_error("cannot write '" + path + "'");
    m_streams.back()->precision(17);
    return *m_streams.back();
  }
  void commit()
  {
    for(auto& s : m_streams)
    {
      s->flush();
      if(!*s) throw std::runtime_error("write error");
      s->close();
    }
    for(const auto& f : m_files)
      if(std::rename(f.second.c_str(), f.first.c_str()) != 0)
        throw std::runtime_error("cannot write '" + f.first + "'");
    m_files.clear();
  }

private:
  std::vector<std::pair<std::string, std::string> > m_files;
  std::vector<std::unique_ptr<std::ofstream> > m_streams;
};

// The colour of part k, as in --parts-glb (sRGB, 0 to 255).
std::array<int, 3> part_colour(std::size_t k)
{
  const std::array<std::uint8_t, 3> c = Part_decomposition_tools::part_rgb(k);
  return {{int(c[0]), int(c[1]), int(c[2])}};
}

struct Result
{
  std::size_t parts = 0;
  std::vector<std::size_t> face_part; // per mesh face, in the iteration order of faces(mesh)
  std::vector<Superquadric> primitives;
  PD::Stage_timings timings;
  PD::Part_hierarchy<K> hierarchy; // with --parts or --hierarchy only
};

Result run(const Mesh& mesh, const Options& o)
{
  Result r;
  std::vector<std::size_t> part(num_faces(mesh), 0);
  auto part_map = CGAL::make_property_map(part); // Surface_mesh face indices are 0..F-1 here
  const auto np = PDP::combine(Part_decomposition_tools::named_parameters(o.decomposition),
                               PDP::primitive_output_iterator(std::back_inserter(r.primitives)),
                               PDP::part_hierarchy(o.decomposition.number_of_parts || !o.hierarchy.empty() ? &r.hierarchy : nullptr),
                               PDP::stage_timings(&r.timings));
  r.parts = PD::decompose(mesh, part_map, np);
  r.face_part.assign(part.begin(), part.end());
  return r;
}

// `file_labels`: the part of each face of the file, in its order (labels_in_file_order()).
void write_labels(std::ostream& out, const std::vector<std::size_t>& file_labels)
{
  for(std::size_t label : file_labels) out << label << '\n';
}

void write_colored(std::ostream& out, const Mesh& mesh, const Result& r)
{
  out << "ply\nformat ascii 1.0\ncomment Hi-TOPS parts: one colour per part\n"
      << "element vertex " << num_vertices(mesh) << "\nproperty double x\nproperty double y\nproperty double z\n"
      << "element face " << num_faces(mesh) << "\nproperty list uchar int vertex_indices\n"
      << "property uchar red\nproperty uchar green\nproperty uchar blue\nproperty int part\nend_header\n";
  std::map<Mesh::Vertex_index, std::size_t> index; // vertices are renumbered densely
  for(Mesh::Vertex_index v : vertices(mesh))
  {
    index.emplace(v, index.size());
    const K::Point_3& p = mesh.point(v);
    out << p.x() << ' ' << p.y() << ' ' << p.z() << '\n';
  }
  std::size_t i = 0;
  for(Mesh::Face_index f : faces(mesh))
  {
    const std::size_t k = r.face_part[i++];
    const std::array<int, 3> c = part_colour(k);
    out << 3;
    for(Mesh::Vertex_index v : vertices_around_face(mesh.halfedge(f), mesh)) out << ' ' << index[v];
    out << ' ' << c[0] << ' ' << c[1] << ' ' << c[2] << ' ' << k << '\n';
  }
}

// A superquadric's JSON members (no braces).
void write_superquadric(std::ostream& out, const Superquadric& q)
{
  const auto R = q.rotation();
  const auto a = q.scales();
  const K::Point_3 c = q.center();
  out << "\"center\":[" << c.x() << ',' << c.y() << ',' << c.z() << "],\"rotation\":[[" << R[0] << ',' << R[1]
      << ',' << R[2] << "],[" << R[3] << ',' << R[4] << ',' << R[5] << "],[" << R[6] << ',' << R[7] << ','
      << R[8] << "]],\"scale\":[" << a[0] << ',' << a[1] << ',' << a[2] << "],\"exponents\":[" << q.epsilon1()
      << ',' << q.epsilon2() << "]";
}

void write_primitives(std::ostream& out, const Result& r)
{
  out << "{\"primitives\":[";
  for(std::size_t k = 0; k < r.primitives.size(); ++k)
  {
    out << (k ? ",\n" : "\n") << "{\"part\":" << k << ',';
    write_superquadric(out, r.primitives[k]);
    out << '}';
  }
  out << "\n]}\n";
}

void write_hierarchy(std::ostream& out, const PD::IO::Mesh_file_info& info, const Result& r)
{
  static const char* const kinds[] = {"leaf", "same_primitive", "same_part", "attached", "same_piece", "contact", "no_contact"};
  const PD::Part_hierarchy<K>& h = r.hierarchy;
  const std::size_t none = PD::Part_hierarchy<K>::Node::no_node;
  out << "{\"leaves\":" << h.number_of_leaves() << ",\"default_number_of_parts\":" << h.default_number_of_parts
      << ",\"root\":" << (h.nodes.empty() ? 0 : h.nodes.size() - 1) << ",\n\"nodes\":[";
  for(std::size_t n = 0; n < h.nodes.size(); ++n)
  {
    const PD::Part_hierarchy<K>::Node& x = h.nodes[n];
    out << (n ? ",\n" : "\n") << "{\"node\":" << n << ",\"children\":[";
    if(x.children[0] != none) out << x.children[0] << ',' << x.children[1];
    out << "],\"parent\":" << (x.parent == none ? std::string("null") : std::to_string(x.parent)) << ",\"kind\":\""
        << kinds[int(x.kind)] << "\",\"merge_cost\":" << x.merge_cost << ",\"area\":" << x.area
        << ",\"faces\":" << x.number_of_faces << ',';
    write_superquadric(out, x.primitive);
    out << '}';
  }
  // the leaf of each face, in the file's face order (faces of Surface_mesh are indexed 0..F-1)
  out << "\n],\n\"leaf_of_face\":[";
  const std::vector<std::size_t> leaf = PD::IO::labels_in_file_order(info, h.leaf);
  for(std::size_t i = 0; i < leaf.size(); ++i) out << (i ? "," : "") << leaf[i];
  out << "]}\n";
}

void write_primitive_mesh(std::ostream& out, const Result& r)
{
  Mesh all;
  for(const Superquadric& q : r.primitives)
  {
    Mesh one;
    q.to_triangle_mesh(one, 24);
    all.join(one);
  }
  if(!CGAL::IO::write_OFF(out, all)) throw std::runtime_error("cannot write the primitive mesh");
}

void print_timings(const std::string& name, const Mesh& mesh, const Result& r, double read_seconds)
{
  const PD::Stage_timings& t = r.timings;
  std::cerr << std::fixed << std::setprecision(3) << name << ": " << num_faces(mesh) << " faces, "
            << r.parts << " parts; seconds: read " << read_seconds << ", prior " << t.prior << ", tsdf "
            << t.tsdf << ", fitting " << t.fitting << ", over-segmentation " << t.over_segmentation
            << ", assignment " << t.assignment << ", hierarchy " << t.hierarchy << ", total " << t.total << std::endl;
}

// What the reader did to the file, for --verbose.
void print_reading(const PD::IO::Mesh_file_info& info)
{
  std::cerr << "read " << info.number_of_input_faces << " faces and " << info.number_of_input_vertices
            << " vertices: " << info.number_of_merged_vertices << " vertices merged (equal), "
            << info.number_of_welded_vertices << " welded (within the weld tolerance), "
            << info.number_of_duplicated_vertices << " duplicated (non-manifold), "
            << info.number_of_triangulated_faces << " polygons triangulated, " << info.dropped_faces.size()
            << " faces without area left out, " << info.number_of_reversed_components
            << " closed components turned outward, " << info.number_of_ignored_values
            << " values beyond the header's properties ignored\n";
}

namespace render = Part_decomposition_tools::render;

// The PNG of the mesh in grey beside its parts; `face_part` in the order of faces(mesh).
std::vector<std::uint8_t> thumbnail_png(const Mesh& mesh, const std::vector<std::size_t>& face_part, const Options& o)
{
  std::vector<render::Vec3> points;
  std::vector<std::array<std::size_t, 3> > triangles;
  render::surface_mesh_arrays(mesh, points, triangles);
  std::vector<render::Rgb> colours;
  for(std::size_t part : face_part) colours.push_back(Part_decomposition_tools::part_rgb(part));
  render::Picture_options picture;
  picture.width = o.thumbnail_width;
  picture.height = o.thumbnail_height;
  return render::encode_png(render::render_input_and_parts(points, triangles, colours, picture));
}

void write_bytes(std::ostream& out, const std::vector<std::uint8_t>& bytes)
{
  out.write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
}

// The stage line of one mesh: on a terminal only, once it took a second; never with --quiet.
Part_decomposition_tools::Progress_line::Mode single_mesh_mode(const Options& o)
{
  typedef Part_decomposition_tools::Progress_line Progress_line;
  return Progress_line::mode_of_stderr(o.quiet) == Progress_line::TERMINAL ? Progress_line::TERMINAL
                                                                          : Progress_line::QUIET;
}

int single(const Options& o)
{
  Part_decomposition_tools::Progress_line progress(single_mesh_mode(o), 0, 1.);
  progress.begin(std::filesystem::path(o.input).filename().string());
  progress.stage("reading");
  const auto t0 = std::chrono::steady_clock::now();
  Mesh mesh;
  const PD::IO::Mesh_file_info info =
    PD::IO::read_triangle_mesh(o.input, mesh, PD::parameters::weld_tolerance(o.decomposition.weld_tolerance));
  if(o.decomposition.verbose) print_reading(info);
  const double read_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  progress.stage("decomposing");
  const Result r = run(mesh, o);

  progress.stage("writing");
  const std::vector<std::size_t> file_labels = PD::IO::labels_in_file_order(info, r.face_part);
  Atomic_outputs outputs;
  if(!o.labels.empty()) write_labels(outputs.open(o.labels), file_labels);
  if(!o.colored.empty()) write_colored(outputs.open(o.colored), mesh, r);
  if(!o.primitives.empty()) write_primitives(outputs.open(o.primitives), r);
  if(!o.primitive_mesh.empty()) write_primitive_mesh(outputs.open(o.primitive_mesh), r);
  if(!o.hierarchy.empty()) write_hierarchy(outputs.open(o.hierarchy), info, r);
  const std::vector<Superquadric> glb_primitives = o.parts_glb_primitives ? r.primitives : std::vector<Superquadric>();
  if(!o.parts_glb.empty() && PD::internal::is_gltf_file(o.input))
    PD::IO::write_gltf_parts_glb(outputs.open(o.parts_glb), o.input, file_labels, r.parts, glb_primitives);
  else if(!o.parts_glb.empty())
    PD::IO::write_parts_glb(outputs.open(o.parts_glb), mesh, r.face_part, r.parts, glb_primitives);
  if(!o.labels_glb.empty())
    PD::IO::write_labels_glb(outputs.open(o.labels_glb), o.input, file_labels, r.parts);
  if(!o.thumbnail.empty()) write_bytes(outputs.open(o.thumbnail), thumbnail_png(mesh, r.face_part, o));
  outputs.commit();
  progress.finish();

  if(o.timings) print_timings(o.input, mesh, r, read_seconds);
  std::cout << o.input << ": " << num_faces(mesh) << " faces, " << r.parts << " parts" << std::endl;
  return EXIT_SUCCESS;
}

std::string stem(const std::string& path)
{
  const std::size_t slash = path.find_last_of('/');
  std::string name = slash == std::string::npos ? path : path.substr(slash + 1);
  const std::size_t dot = name.find_last_of('.');
  return dot == std::string::npos || dot == 0 ? name : name.substr(0, dot);
}

bool file_exists(const std::string& path)
{
  return std::ifstream(path).good();
}

// The paths of the list file: one per line, blank lines and '#' comments skipped.
std::vector<std::string> read_list(const std::string& list_path)
{
  std::ifstream list(list_path);
  if(!list) throw Usage_error("cannot read the list '" + list_path + "'");
  std::vector<std::string> paths;
  for(std::string line; std::getline(list, line);)
  {
    while(!line.empty() && (line.back() == '\r' || line.back() == ' ' || line.back() == '\t')) line.pop_back();
    std::size_t b = line.find_first_not_of(" \t");
    if(b == std::string::npos || line[b] == '#') continue;
    paths.push_back(line.substr(b));
  }
  return paths;
}

// What became of one mesh of a batch: ok, failed or timeout, and its columns of the summary.
struct Mesh_outcome
{
  std::string status = "failed";
  std::size_t faces = 0, parts = 0;
  std::string message; // on one line, without tabs
};

std::string one_line(std::string message)
{
  for(char& c : message)
    if(c == '\t' || c == '\n') c = ' ';
  return message;
}

// The output files of one mesh of a batch; png is empty without --report.
struct Mesh_files
{
  std::string seg, json, png;
};

// Tells what one mesh of a batch does now.
typedef std::function<void(const char*)> Stage_callback;

// Reads, decomposes and writes the outputs of one mesh of a batch; an error is the outcome.
Mesh_outcome decompose_one(const Options& o, const std::string& path, const Mesh_files& files, const Stage_callback& stage)
{
  Mesh_outcome outcome;
  try
  {
    stage("reading");
    Mesh mesh;
    const PD::IO::Mesh_file_info info =
      PD::IO::read_triangle_mesh(path, mesh, PD::parameters::weld_tolerance(o.decomposition.weld_tolerance));
    if(o.decomposition.verbose) print_reading(info);
    stage("decomposing");
    const Result r = run(mesh, o);
    stage("writing");
    Atomic_outputs outputs;
    write_labels(outputs.open(files.seg), PD::IO::labels_in_file_order(info, r.face_part));
    write_primitives(outputs.open(files.json), r);
    if(!files.png.empty()) write_bytes(outputs.open(files.png), thumbnail_png(mesh, r.face_part, o));
    outputs.commit();
    if(o.timings) print_timings(path, mesh, r, 0.);
    outcome.status = "ok";
    outcome.faces = info.number_of_input_faces;
    outcome.parts = r.parts;
  }
  catch(const std::exception& e)
  {
    outcome.message = one_line(e.what());
  }
  catch(...)
  {
    outcome.message = "unexpected exception";
  }
  return outcome;
}

// Writes all of `text` to the file descriptor `fd`.
void write_all(int fd, const std::string& text)
{
  for(std::size_t done = 0; done < text.size();)
  {
    const ssize_t n = ::write(fd, text.data() + done, text.size() - done);
    if(n < 0 && errno == EINTR) continue;
    if(n <= 0) return;
    done += std::size_t(n);
  }
}

// Reads what the child writes to `fd` until it closes it (true) or `deadline` passes (false).
bool read_until_closed(int fd, std::chrono::steady_clock::time_point deadline, std::string& text)
{
  char buffer[4096];
  for(;;)
  {
    const auto now = std::chrono::steady_clock::now();
    if(now >= deadline) return false;
    // rounded up: poll() must not return just before the deadline and spin
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - now).count() + 1;
    pollfd p = {fd, POLLIN, 0};
    const int ready = ::poll(&p, 1, int((std::min)(left, std::chrono::milliseconds::rep(1 << 30))));
    if(ready < 0 && errno == EINTR) continue;
    if(ready <= 0) continue; // the deadline is checked again
    const ssize_t n = ::read(fd, buffer, sizeof(buffer));
    if(n < 0 && errno == EINTR) continue;
    if(n <= 0) return true;
    text.append(buffer, std::size_t(n));
  }
}

// decompose_one() in a child process, killed if it takes longer than o.mesh_timeout seconds; the
// child sends its outcome through a pipe. A killed child leaves no output, complete or not.
Mesh_outcome decompose_with_timeout(const Options& o, const std::string& path, const Mesh_files& files,
                                    Part_decomposition_tools::Progress_line& progress)
{
  int channel[2];
  if(::pipe(channel) != 0) throw std::runtime_error("cannot create a pipe");
  std::cout.flush();
  std::unique_lock<std::mutex> quiet_progress = progress.hold();
  const pid_t child = ::fork();
  if(child < 0) throw std::runtime_error("cannot start a process for '" + path + "'");
  if(child == 0)
  {
    ::close(channel[0]);
    // the progress belongs to the parent (its lock stays held here): the child draws nothing
    const Mesh_outcome m = decompose_one(o, path, files, [](const char*) {});
    write_all(channel[1],
              m.status + '\t' + std::to_string(m.faces) + '\t' + std::to_string(m.parts) + '\t' + m.message);
    // no destructor of the parent's objects (its summary, with its temporary file) may run here
    std::cerr.flush();
    ::_exit(EXIT_SUCCESS);
  }
  quiet_progress.unlock();
  ::close(channel[1]);
  // at most 30 years: the clock's range is not exceeded
  const std::chrono::duration<double> timeout((std::min)(o.mesh_timeout, 1e9));
  const auto deadline =
    std::chrono::steady_clock::now() + std::chrono::duration_cast<std::chrono::steady_clock::duration>(timeout);
  std::string text;
  const bool finished = read_until_closed(channel[0], deadline, text);
  ::close(channel[0]);
  if(!finished) ::kill(child, SIGKILL);
  int status = 0;
  while(::waitpid(child, &status, 0) < 0 && errno == EINTR) {}

  Mesh_outcome outcome;
  std::istringstream in(text);
  if(finished && std::getline(in, outcome.status, '\t') && (in >> outcome.faces >> outcome.parts))
  {
    in.get(); // the tab before the message
    std::getline(in, outcome.message);
    return outcome;
  }
  // killed, or the child died without an outcome (a crash): its outputs are not complete
  for(const std::string& f : {files.seg, files.json, files.png})
  {
    if(f.empty()) continue;
    std::remove((f + ".tmp." + std::to_string(child)).c_str());
    std::remove(f.c_str());
  }
  outcome = Mesh_outcome();
  if(!finished)
  {
    outcome.status = "timeout";
    std::ostringstream message;
    message << "stopped after " << o.mesh_timeout << " s (--mesh-timeout)";
    outcome.message = message.str();
  }
  else if(WIFSIGNALED(status)) outcome.message = "killed by signal " + std::to_string(WTERMSIG(status));
  else outcome.message = "the process ended without a result";
  return outcome;
}

// The faces and parts of a label file (one label per line): a mesh done by an earlier run.
bool label_file_counts(const std::string& seg, std::vector<std::size_t>& labels, Mesh_outcome& outcome)
{
  std::ifstream in(seg);
  labels.clear();
  for(std::size_t l; in >> l;) labels.push_back(l);
  if(!in.eof() || labels.empty()) return false;
  outcome.faces = labels.size();
  outcome.parts = *std::max_element(labels.begin(), labels.end()) + 1;
  return true;
}

// The thumbnail of a mesh done by an earlier run, from its input and label file; false if either
// cannot be read or they do not fit.
bool thumbnail_of_outputs(const Options& o, const std::string& path, const std::vector<std::size_t>& labels,
                          const std::string& png)
{
  try
  {
    Mesh mesh;
    const PD::IO::Mesh_file_info info =
      PD::IO::read_triangle_mesh(path, mesh, PD::parameters::weld_tolerance(o.decomposition.weld_tolerance));
    if(labels.size() != info.number_of_input_faces) return false;
    std::vector<std::size_t> face_part;
    for(std::size_t input_face : info.face_to_input) face_part.push_back(labels[input_face]);
    Atomic_outputs outputs;
    write_bytes(outputs.open(png), thumbnail_png(mesh, face_part, o));
    outputs.commit();
    return true;
  }
  catch(const std::exception&)
  {
    return false;
  }
}

// One mesh of a batch as its summary row and its report entry give it.
struct Batch_entry
{
  std::string name, input;
  Mesh_files files;
  Mesh_outcome outcome;
  double seconds = 0.;
};

std::string html_escaped(const std::string& text)
{
  std::string out;
  for(char c : text)
  {
    if(c == '&') out += "&amp;";
    else if(c == '<') out += "&lt;";
    else if(c == '>') out += "&gt;";
    else if(c == '"') out += "&quot;";
    else if(c == '\'') out += "&#39;";
    else out += c;
  }
  return out;
}

// A relative URL of a file path: every byte but unreserved characters and '/' percent-encoded.
std::string url_of_path(const std::string& path)
{
  static const char* const hex = "0123456789ABCDEF";
  std::string out;
  for(unsigned char c : path)
  {
    if(std::isalnum(c) || c == '-' || c == '_' || c == '.' || c == '~' || c == '/') out += char(c);
    else out += std::string("%") + hex[c >> 4] + hex[c & 15];
  }
  return out;
}

// The input of a mesh relative to the report's folder, empty if it does not exist.
std::string input_relative_to(const std::string& input, const std::string& folder)
{
  std::error_code ec;
  if(!file_exists(input)) return std::string();
  const std::filesystem::path from = std::filesystem::absolute(folder, ec), to = std::filesystem::absolute(input, ec);
  const std::filesystem::path relative = ec ? std::filesystem::path() : std::filesystem::relative(to, from, ec);
  return ec || relative.empty() ? std::string() : relative.generic_string();
}

// One figure of the contact sheet: the thumbnail, or the error in its place; the numbers; links.
void write_report_entry(std::ostream& out, const Options& o, const Batch_entry& e)
{
  const Mesh_outcome& m = e.outcome;
  const std::string name = html_escaped(e.name);
  const std::string png = "thumbnails/" + e.name + ".png";
  const bool picture = !e.files.png.empty() && file_exists(e.files.png) && (m.status == "ok" || m.status == "skipped");
  out << "<figure class=\"mesh " << m.status << "\" id=\"" << name << "\">\n";
  if(picture)
    out << "<a href=\"" << url_of_path(png) << "\"><img src=\"" << url_of_path(png) << "\" width=\"" << o.thumbnail_width
        << "\" height=\"" << o.thumbnail_height << "\" alt=\"" << name << ": the input and its " << m.parts
        << " parts\"></a>\n";
  else
    out << "<div class=\"error\" style=\"width:" << o.thumbnail_width << "px;height:" << o.thumbnail_height << "px\">"
        << html_escaped(m.status) << (m.message.empty() ? "" : ": ") << html_escaped(m.message) << "</div>\n";
  out << "<figcaption><b>" << name << "</b> <span class=\"status\">" << html_escaped(m.status) << "</span><br>";
  if(m.faces > 0) out << m.faces << " faces, " << m.parts << " parts";
  if(m.status != "skipped") out << (m.faces > 0 ? ", " : "") << std::fixed << std::setprecision(2) << e.seconds << " s";
  if(!m.message.empty() && picture) out << "<br><span class=\"message\">" << html_escaped(m.message) << "</span>";
  const std::string input = input_relative_to(e.input, o.out_dir);
  if(!input.empty() || file_exists(e.files.seg)) out << "<br>";
  if(!input.empty()) out << "<a href=\"" << url_of_path(input) << "\">input</a> ";
  if(file_exists(e.files.seg)) out << "<a href=\"" << url_of_path(e.name + ".seg") << "\">labels</a> ";
  if(file_exists(e.files.json)) out << "<a href=\"" << url_of_path(e.name + ".json") << "\">primitives</a>";
  out << "</figcaption>\n</figure>\n";
}

// The contact sheet of a batch: one figure per mesh, inline CSS, no script.
void write_report(std::ostream& out, const Options& o, const std::vector<Batch_entry>& entries,
                  std::map<std::string, std::size_t>& count, double seconds)
{
  out << "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n<title>hitops: "
      << html_escaped(o.batch) << "</title>\n<style>\n"
      << "body{font-family:sans-serif;margin:1em;background:#f4f4f4;color:#222}\n"
      << "main{display:flex;flex-wrap:wrap;gap:10px}\n"
      << "figure{margin:0;padding:6px;background:#fff;border:1px solid #ccc;border-radius:4px;font-size:13px}\n"
      << "figure img{display:block;border:0}\n"
      << "figure.failed,figure.timeout{border-color:#c33}\n"
      << ".error{box-sizing:border-box;overflow:auto;padding:6px;background:#fbe9e9;color:#a00;font-family:monospace}\n"
      << ".status{color:#666}.failed .status,.timeout .status{color:#a00}.message{color:#a60}\n"
      << "</style>\n</head>\n<body>\n<h1>hitops: " << html_escaped(o.batch) << "</h1>\n<p>" << entries.size()
      << " meshes: " << count["ok"] << " decomposed, " << count["skipped"] << " skipped, " << count["failed"]
      << " failed, " << count["timeout"] << " timed out; " << std::fixed << std::setprecision(1) << seconds
      << " s. Left of each picture the input, right its parts.</p>\n<main>\n";
  for(const Batch_entry& e : entries) write_report_entry(out, o, e);
  out << "</main>\n</body>\n</html>\n";
}

// What a mesh of the batch line says after its status.
std::string outcome_detail(const Mesh_outcome& m, double seconds)
{
  std::ostringstream detail;
  detail << std::fixed << std::setprecision(2);
  if(m.status == "ok") detail << m.faces << " faces, " << m.parts << " parts, " << seconds << " s";
  else if(m.status == "skipped") detail << m.message;
  else detail << seconds << " s: " << m.message;
  return detail.str();
}

// Decomposes one mesh of the batch, or skips it if its outputs exist (then draws its missing
// thumbnail for the report).
void process(const Options& o, Batch_entry& e, Part_decomposition_tools::Progress_line& progress)
{
  const auto t0 = std::chrono::steady_clock::now();
  if(file_exists(e.files.seg) && file_exists(e.files.json))
  {
    e.outcome.status = "skipped";
    e.outcome.message = "already done";
    std::vector<std::size_t> labels;
    if(!e.files.png.empty() && label_file_counts(e.files.seg, labels, e.outcome) && !file_exists(e.files.png))
    {
      progress.stage("drawing");
      thumbnail_of_outputs(o, e.input, labels, e.files.png);
    }
  }
  else if(o.mesh_timeout > 0)
  {
    progress.stage("in a child process");
    e.outcome = decompose_with_timeout(o, e.input, e.files, progress);
  }
  else
    e.outcome = decompose_one(o, e.input, e.files, [&progress](const char* stage) { progress.stage(stage); });
  e.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

// One line per mesh of the shard: name, input, status, faces, parts, seconds, sha256, message.
int batch(const Options& o)
{
  const auto start = std::chrono::steady_clock::now();
  const std::vector<std::string> paths = read_list(o.batch);
  // names must be unique in the output folder: repeated stems get their rank appended
  std::map<std::string, std::size_t> stem_count;
  for(const std::string& p : paths) ++stem_count[stem(p)];

  // shards on many machines may all create the folder: an existing one is fine
  std::error_code ec;
  std::filesystem::create_directories(o.report ? o.out_dir + "/thumbnails" : o.out_dir, ec);
  if(ec) throw Usage_error("cannot create the output folder '" + o.out_dir + "': " + ec.message());

  const std::string suffix = o.shards > 1 ? "." + std::to_string(o.shard) + "-of-" + std::to_string(o.shards) : "";
  Atomic_outputs summary_file;
  std::ostream& summary = summary_file.open(o.out_dir + "/summary" + suffix + ".tsv");
  summary << "name\tinput\tstatus\tfaces\tparts\tseconds\tsha256\tmessage\n";
  std::map<std::string, std::size_t> count; // per status
  const std::size_t share = paths.size() / o.shards + (o.shard < paths.size() % o.shards ? 1 : 0);
  typedef Part_decomposition_tools::Progress_line Progress_line;
  Progress_line progress(Progress_line::mode_of_stderr(o.quiet), share);
  std::vector<Batch_entry> entries;
  for(std::size_t i = o.shard; i < paths.size(); i += o.shards)
  {
    Batch_entry e;
    e.input = paths[i];
    e.name = stem_count[stem(paths[i])] > 1 ? stem(paths[i]) + "_" + std::to_string(i) : stem(paths[i]);
    e.files = {o.out_dir + "/" + e.name + ".seg", o.out_dir + "/" + e.name + ".json",
               o.report ? o.out_dir + "/thumbnails/" + e.name + ".png" : std::string()};
    std::string sha256; // empty if the file cannot be read
    Part_decomposition_tools::sha256_of_file(paths[i], sha256);
    progress.begin(e.name);
    process(o, e, progress);
    const Mesh_outcome& outcome = e.outcome;
    const bool ok = outcome.status == "ok";
    summary << e.name << '\t' << paths[i] << '\t' << outcome.status << '\t';
    if(ok) summary << outcome.faces << '\t' << outcome.parts;
    else summary << '\t';
    summary << '\t';
    if(outcome.status != "skipped") summary << e.seconds;
    summary << '\t' << sha256 << '\t' << outcome.message << '\n';
    progress.end(outcome.status, outcome_detail(outcome, e.seconds), e.seconds);
    // one line per mesh already names the failures
    if(!ok && outcome.status != "skipped" && progress.mode() != Progress_line::LINES)
      progress.message("hitops: " + paths[i] + ": " + outcome.message);
    ++count[outcome.status];
    summary.flush();
    if(o.report) entries.push_back(e);
  }
  progress.finish();
  if(o.report)
    write_report(summary_file.open(o.out_dir + "/report" + suffix + ".html"), o, entries, count,
                 std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  summary_file.commit();
  std::cout << "batch: " << count["ok"] << " decomposed, " << count["skipped"] << " skipped, " << count["failed"]
            << " failed, " << count["timeout"] << " timed out" << std::endl;
  return count["failed"] + count["timeout"] == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}

} // namespace

int main(int argc, char** argv)
{
  try
  {
    const Options o = parse(argc, argv);
#ifdef CGAL_LINKED_WITH_TBB
    std::unique_ptr<tbb::global_control> limit;
    if(o.threads > 0)
      limit.reset(new tbb::global_control(tbb::global_control::max_allowed_parallelism, std::size_t(o.threads)));
#endif
    return o.batch.empty() ? single(o) : batch(o);
  }
  catch(const std::exception& e)
  {
    std::string message = e.what();
    for(char& c : message)
      if(c == '\n') c = ' ';
    std::cerr << "hitops: error: " << message << std::endl;
    return EXIT_FAILURE;
  }
  catch(...)
  {
    std::cerr << "hitops: error: unexpected exception" << std::endl;
    return EXIT_FAILURE;
  }
}
