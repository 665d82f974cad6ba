#include "demo_command.h"

#include "Durable/atomic_output.h"
#include "Morph/morph_text.h"
#include "map_command.h"
#include "mesh_command.h"
#include "morph_command.h"
#include "user_error.h"

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <unistd.h>

#include <array>
#include <chrono>
#include <climits>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>

namespace fs = std::filesystem;

namespace frepkit
{
namespace
{

// The Examples folder: <bin>/../share/frepkit/examples beside the running tool, in an
// installation (<prefix>/bin/frepkit) and in the build tree alike (build/share/frepkit/examples
// is a link to the source tree's Examples/); no path of the build machine is compiled in.
fs::path find_examples(const std::string& requested)
{
  if (!requested.empty())
  {
    return requested;
  }
  std::vector<fs::path> candidates;
  char executable[PATH_MAX];
  const ssize_t length = ::readlink("/proc/self/exe", executable, sizeof executable - 1);
  if (length > 0)
  {
    const fs::path bin =
      fs::path(std::string(executable, static_cast<std::size_t>(length))).parent_path();
    candidates.push_back(bin.parent_path() / "share" / "frepkit" / "examples");
  }
  for (const fs::path& c : candidates)
  {
    if (fs::exists(c / "homotopic" / "homotopic.json"))
    {
      return c;
    }
  }
  throw UserError(
    "cannot find the examples (Examples/homotopic/homotopic.json); give --examples DIR");
}

// The keys of Meta5D on the paper's 2 x 2 lattice, first parameter (x4) fastest.
constexpr std::array<const char*, 4> key_shapes{ "cat", "robot", "nihon", "roblet" };

// Meta5D as the metamorphosis component writes it (Morph's write_morph) from the four key files,
// pasted into one HyperFun file in the output folder: the model drawn is there to evaluate
// again, by frepkit or the original interpreter. With --align none it is the paper's formula
// (bit for bit Examples/homotopic/meta5d.hf); aligned, the keys travel and grow into each other.
frep::morph::MorphSpec meta5d_spec(const fs::path& examples,
  frep::morph::Alignment alignment,
  frep::morph::Normalisation normalisation)
{
  frep::morph::MorphSpec spec;
  for (const char* key : key_shapes)
  {
    spec.keys.push_back({ (examples / (std::string(key) + ".hf")).string(), key });
  }
  spec.lattice = { 2, 2 };
  spec.alignment = alignment;
  spec.normalisation = normalisation;
  spec.name = "meta5d";
  return spec;
}

// meta5d.hf in `out`, and with distances the keys' volumes beside it; returns the --shape
// arguments that load it (none without distances).
std::vector<std::string> write_meta5d(const frep::morph::MorphSpec& spec, const fs::path& model)
{
  const frep::morph::MorphText morph =
    frep::morph::write_morph(spec, frep::morph::KeyPlacement::Pasted);
  if (!morph.ok())
  {
    std::cerr << frep::format_diagnostics(morph.diagnostics);
    throw UserError("writing Meta5D from the key shapes failed; nothing drawn");
  }
  fs::create_directories(model.parent_path());
  std::vector<std::string> shapes = write_distances(morph, model.string());
  frep::durable::AtomicOutput file(model.string());
  file.stream() << morph.text;
  file.commit();
  return shapes;
}

nlohmann::json morph_json(const frep::morph::MorphSpec& spec)
{
  nlohmann::json keys = nlohmann::json::array();
  for (const frep::morph::Key& key : spec.keys)
  {
    keys.push_back(
      { { "file", fs::path(key.file).filename().string() }, { "object", key.object } });
  }
  nlohmann::json key_weights = nlohmann::json::object();
  for (const frep::morph::KeyWeight& weight : spec.key_weights)
    key_weights[weight.key] = weight.expression;
  return { { "keys", keys },
    { "lattice", spec.lattice },
    { "scheme", frep::morph::interpolation_name(spec.scheme) },
    { "alignment", frep::morph::alignment_name(spec.alignment) },
    { "normalisation", frep::morph::normalisation_name(spec.normalisation) },
    { "timing", frep::morph::timing_name(spec.timing) },
    { "key_weights", key_weights } };
}

std::size_t stl_triangles(const fs::path& stl)
{
  std::error_code ec;
  const auto size = fs::file_size(stl, ec);
  return ec || size < 84 ? 0 : static_cast<std::size_t>((size - 84) / 50);
}

} // namespace

CLI::App* add_demo_command(CLI::App& app, DemoOptions& o)
{
  CLI::App* cmd = app.add_subcommand("demo",
    "The main job: 'Homotopic Fun in 5D Space' end to end (key shapes as STL, the 5x5 "
    "spreadsheet, the path, the animation with sound as MP4, a manifest)");
  cmd->add_option("name", o.name, "the demo (only 'homotopic')")
    ->check(CLI::IsMember({ "homotopic" }));
  cmd->add_option("-O,--output-directory", o.output_directory, "directory for the outputs")
    ->required();
  cmd->add_option(
    "--examples", o.examples, "the Examples folder (default: found next to the tool)");
  cmd->add_option("--frames", o.frames, "number of frames (default: the mapping's 240)")
    ->check(CLI::Range(1, 100000));
  cmd->add_option("--resolution", o.resolution, "grid samples per cell and frame (default 128)")
    ->check(CLI::Range(8, 1024));
  cmd
    ->add_option("--ghost",
      o.ghost,
      "resolution of the ghost (ghost.png: the union of every shape of the animation, Meta5D "
      "projected along its path; default: the mapping's 32), 0 for none")
    ->check(CLI::Range(0, 1024) & !CLI::Range(1, 1));
  cmd
    ->add_option("--topology",
      o.topology,
      "resolution of the map of the topology (every cell's and frame's pieces and genus, where "
      "they change; default: the mapping's 96), 0 for none")
    ->check(CLI::Range(0, 1024) & !CLI::Range(1, 1));
  cmd
    ->add_option("--method",
      o.method,
      "draw cells and frames by 'mesh' (quick drafts) or 'raycast' (default: the mapping's: "
      "ray-cast spreadsheet, meshed frames)")
    ->check(CLI::IsMember({ "mesh", "raycast" }));
  cmd->add_option("--mesh-grid", o.mesh_grid, "grid of the key shapes' STL meshes (default 256)")
    ->check(CLI::Range(8, 2048));
  cmd
    ->add_option("--align",
      o.align,
      "how Meta5D blends its keys: size (each key travels and grows into the blended centroid "
      "and size), centroid, or none (the paper's formula as it stands)")
    ->check(CLI::IsMember({ "none", "centroid", "size" }))
    ->capture_default_str();
  cmd
    ->add_option("--normalise",
      o.normalise,
      "Meta5D's keys' values: none (as the key files give them) or distance (each key's "
      "sampled signed distance added beyond a band about its surface, written beside "
      "meta5d.hf as meta5d-KEY-distance.vti)")
    ->check(CLI::IsMember({ "none", "distance" }))
    ->capture_default_str();
  add_blend_options(*cmd, o.blend);
  cmd->add_flag("--force", o.force, "render every frame again");
  cmd->add_option("-j,--threads", o.threads, "worker threads (default: all cores)")
    ->check(CLI::Range(0, 1024));
  cmd->add_flag("-q,--quiet", o.quiet, "no progress bar and no summary");
  return cmd;
}

int run_demo(const DemoOptions& options)
{
  const auto start = std::chrono::steady_clock::now();
  const fs::path examples = find_examples(options.examples) / "homotopic";
  const fs::path out(options.output_directory);

  // 1. The model, written from the key files; then the mapping (it validates everything
  // before writing any picture).
  frep::morph::MorphSpec morph = meta5d_spec(examples,
    *frep::morph::alignment_from_name(options.align),
    *frep::morph::normalisation_from_name(options.normalise));
  apply_blend_options(options.blend, morph);
  require_normalisation_files(morph.normalisation);
  const fs::path model = out / "meta5d.hf";
  MapOptions map;
  map.user.shapes = write_meta5d(morph, model);
  map.model = model.string();
  map.mapping = (examples / "homotopic.json").string();
  map.output_directory = out.string();
  map.name = "homotopic";
  map.frames = options.frames;
  map.resolution = options.resolution;
  map.ghost = options.ghost;
  map.topology = options.topology;
  map.method = options.method;
  map.force = options.force;
  map.threads = options.threads;
  map.quiet = options.quiet;
  std::string map_manifest; // the map's manifest, completed below: manifest.json is written once
  map.manifest_out = &map_manifest;
  const int code = run_map(map);
  if (code != 0)
  {
    return code;
  }

  // 2. The four key shapes, each from its own file, on the common box.
  nlohmann::json meshes = nlohmann::json::array();
  const auto t0 = std::chrono::steady_clock::now();
  for (const char* shape : key_shapes)
  {
    MeshOptions mesh;
    mesh.model = (examples / (std::string(shape) + ".hf")).string();
    mesh.output = (out / (std::string(shape) + ".stl")).string();
    mesh.box = { "-10", "-10", "-10", "10", "10", "10" };
    mesh.grid = { options.mesh_grid };
    mesh.threads = options.threads;
    mesh.quiet = true;
    if (run_mesh(mesh) != 0)
    {
      throw UserError(std::string("meshing ") + shape + " failed");
    }
    meshes.push_back({ { "file", std::string(shape) + ".stl" },
      { "kind", "mesh" },
      { "model", mesh.model },
      { "grid", options.mesh_grid },
      { "triangles", stl_triangles(mesh.output) } });
  }
  const double mesh_seconds =
    std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();

  // 3. One manifest: the map's, with the meshes added.
  const fs::path manifest_path = out / "manifest.json";
  nlohmann::json manifest = nlohmann::json::parse(map_manifest, nullptr, false);
  if (manifest.is_discarded() || !manifest.is_object())
  {
    throw UserError("internal error: the map's manifest is not a JSON object");
  }
  manifest["demo"] = "Homotopic Fun in 5D Space";
  manifest["model"] = model.filename().string(); // in the output folder, beside the manifest
  manifest["morph"] = morph_json(morph);
  for (const std::string& shape : map.user.shapes) // "mdist_cat=<out>/meta5d-cat-distance.vti"
  {
    const std::size_t equals = shape.find('=');
    manifest["morph"]["shapes"][shape.substr(0, equals)] =
      fs::path(shape.substr(equals + 1)).filename().string();
  }
  for (auto& m : meshes)
  {
    manifest["files"].push_back(m);
  }
  manifest["seconds"]["meshes"] = mesh_seconds;
  const double total =
    std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  manifest["seconds"]["total"] = total;
  {
    frep::durable::AtomicOutput file(manifest_path.string());
    file.stream() << manifest.dump(2) << "\n";
    file.commit();
  }
  if (!options.quiet)
  {
    char line[200];
    std::snprintf(line,
      sizeof line,
      "  %-12s %7.2f s  cat.stl robot.stl nihon.stl roblet.stl (grid %d)\n",
      "key shapes",
      mesh_seconds,
      options.mesh_grid);
    std::cerr << line;
    std::snprintf(line,
      sizeof line,
      "  %-12s %7.2f s  everything in %s\n",
      "demo",
      total,
      out.string().c_str());
    std::cerr << line;
  }
  return 0;
}

} // namespace frepkit
