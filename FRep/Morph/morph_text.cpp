#include "Morph/morph_text.h"

#include "Morph/detail/key_weight_check.h"
#include "Morph/detail/weight_text.h"
#include "Language/names.h"
#include "Shapes/shape_functions.h"

#include <algorithm>
#include <cctype>
#include <fstream>
#include <iterator>
#include <map>
#include <set>

namespace frep::morph
{
namespace
{

// A key's object, as read from its file.
struct KeyObject
{
  std::string file;
  std::string name; // lower-case
  SourceLocation at;
  int x_dim = 0, a_dim = 0, s_dim = 1;
};

// A key file, read once however many nodes use it.
struct KeyFile
{
  std::string path;
  LoadedProgram program;            // parsed once: its objects are compiled from it
  std::vector<std::string> objects; // its own objects' names, lower-case
  std::vector<SourceLocation> places;
  int first_line = 1; // of its first own object
};

Diagnostic error(const std::string& file, SourceLocation at, std::string message)
{
  return Diagnostic{ file, at, std::move(message) };
}

// Loads each distinct key file once and picks every key's object.
bool read_keys(const MorphSpec& spec,
  const LoadOptions& key_options,
  std::vector<KeyObject>& keys,
  std::vector<KeyFile>& files,
  std::vector<Diagnostic>& diagnostics)
{
  LoadOptions options = key_options;
  options.object.clear();
  std::map<std::string, LoadedProgram> loaded;
  for (const Key& key : spec.keys)
  {
    auto found = loaded.find(key.file);
    if (found == loaded.end())
    {
      found = loaded.emplace(key.file, load_program(ModelSource::file(key.file), options)).first;
      const LoadedProgram& program = found->second;
      if (!program.ok())
      {
        diagnostics.insert(
          diagnostics.end(), program.diagnostics.begin(), program.diagnostics.end());
        continue;
      }
      KeyFile file;
      file.path = key.file;
      const auto& objects = program.program->objects;
      for (std::size_t i = static_cast<std::size_t>(program.program->first_own_object);
           i < objects.size();
           ++i)
      {
        file.objects.push_back(objects[i].name);
        file.places.push_back(objects[i].location);
      }
      file.first_line = file.places.empty() ? 1 : file.places.front().line;
      file.program = program;
      files.push_back(std::move(file));
    }
    if (!found->second.ok())
      continue;
    const int index = choose_object(found->second, key.object, diagnostics);
    if (index < 0)
      continue;
    const ast::Object& object = found->second.program->objects[static_cast<std::size_t>(index)];
    keys.push_back(KeyObject{
      key.file, object.name, object.location, object.x_dim, object.a_dim, object.s_dim });
  }
  return diagnostics.empty();
}

std::string lattice_text(const std::vector<int>& lattice)
{
  std::string text;
  for (std::size_t a = 0; a < lattice.size(); ++a)
    text += (a ? " x " : "") + std::to_string(lattice[a]);
  return text;
}

// The lattice and the name, before any file is read.
bool check_spec(const MorphSpec& spec, std::vector<Diagnostic>& diagnostics)
{
  const std::string here = "metamorphosis";
  if (!is_identifier(spec.name))
    diagnostics.push_back(error(here,
      {},
      "'" + spec.name +
        "' is not a HyperFun object name "
        "(a letter, then letters, digits or _)"));
  if (spec.lattice.empty())
    diagnostics.push_back(error(here, {}, "the lattice has no axis"));
  std::size_t nodes = 1;
  for (const int n : spec.lattice)
  {
    if (n < 2 || n > 64)
    {
      diagnostics.push_back(error(here,
        {},
        "a lattice axis needs 2 to 64 nodes (the lattice " + lattice_text(spec.lattice) + ")"));
      return false;
    }
    nodes *= static_cast<std::size_t>(n);
  }
  if (diagnostics.empty() && nodes != spec.keys.size())
    diagnostics.push_back(error(here,
      {},
      "the lattice " + lattice_text(spec.lattice) + " has " + std::to_string(nodes) + " nodes, " +
        std::to_string(spec.keys.size()) + " keys were given"));
  return diagnostics.empty();
}

// Every key the same size; no object name twice among the key files and the ones written.
bool check_keys(const MorphSpec& spec,
  const std::vector<KeyObject>& keys,
  const std::vector<KeyFile>& files,
  std::vector<Diagnostic>& diagnostics)
{
  const KeyObject& first = keys.front();
  for (const KeyObject& key : keys)
  {
    const auto describe = [](const KeyObject& k)
    { return k.name + "(x[" + std::to_string(k.x_dim) + "], a[" + std::to_string(k.a_dim) + "])"; };
    if (key.x_dim != first.x_dim || key.a_dim != first.a_dim)
      diagnostics.push_back(error(key.file,
        key.at,
        "the key " + describe(key) + " and the key " + describe(first) + " (" + first.file +
          ") differ: every key needs the same x[] and a[] sizes"));
    if (key.s_dim != 1)
      diagnostics.push_back(error(key.file,
        key.at,
        "the key " + key.name + " has s[" + std::to_string(key.s_dim) +
          "]: attributes are not blended yet, so a key must have s[1]"));
  }
  std::map<std::string, std::string> owner; // object name -> its key file
  for (const KeyFile& file : files)
  {
    for (std::size_t i = 0; i < file.objects.size(); ++i)
    {
      const auto [it, fresh] = owner.emplace(file.objects[i], file.path);
      if (!fresh)
        diagnostics.push_back(error(file.path,
          file.places[i],
          "the object '" + file.objects[i] + "' is defined in " + it->second +
            " too: the key files' objects need different names"));
    }
  }
  for (const std::string& written : { lower_case(spec.name), std::string("my_model") })
  {
    if (const auto it = owner.find(written); it != owner.end())
      diagnostics.push_back(error(it->second,
        {},
        "the key file defines '" + written +
          "', an object the metamorphosis writes: rename it, or name the metamorphosis otherwise"));
  }
  return diagnostics.empty();
}

// "-- text\n", cut to the original's limit (a comment over 256 characters is a syntax error).
std::string comment(const std::string& text)
{
  constexpr std::size_t kLongest = 250;
  return "--" + (text.size() > kLongest ? text.substr(0, kLongest - 3) + "..." : text) + "\n";
}

std::string header(const MorphSpec& spec,
  const std::vector<KeyObject>& keys,
  int d,
  KeyPlacement placement)
{
  const std::size_t axes = spec.lattice.size();
  std::string out =
    comment(
      " Metamorphosis written by FRepKit (frepkit morph): " + std::to_string(keys.size()) +
      " keys on a " + lattice_text(spec.lattice) + " lattice, " +
      std::string(interpolation_name(spec.scheme)) + " weights" +
      (spec.alignment == Alignment::None        ? std::string()
        : spec.alignment == Alignment::Centroid ? ", keys aligned by their centroids"
                                                : ", keys aligned by their centroids and sizes") +
      ".") +
    comment(" x[1.." + std::to_string(d) + "]: the keys' coordinates; x[" + std::to_string(d + 1) +
            "]" + (axes > 1 ? "..x[" + std::to_string(d + static_cast<int>(axes)) + "]" : "") +
            ": the lattice's parameters, each over [0, 1] (clamped); node i of n at i/(n-1).") +
    comment(" Keys (x[" + std::to_string(d + 1) + "] fastest):");
  for (std::size_t k = 0; k < keys.size(); ++k)
  {
    std::string line = "  ";
    const std::vector<int> nodes = weight_text::lattice_indices(k, spec.lattice);
    for (std::size_t a = 0; a < axes; ++a)
      line += " x[" + std::to_string(d + 1 + static_cast<int>(a)) +
              "] = " + weight_text::node_value(nodes[a], spec.lattice[a]);
    out += comment(line + ": " + keys[k].name + " (" + keys[k].file + ")");
  }
  if (spec.timing.curve != TimingCurve::Linear)
    out += comment(" Timed: " + timing_name(spec.timing) + " between neighbouring keys.");
  for (const KeyWeight& weight : spec.key_weights)
    out += comment(" Key weight of " + lower_case(weight.key) + ": " + weight.expression);
  if (spec.normalisation == Normalisation::Distance)
  {
    out += comment(
      " Keys normalised by distance: each key's F plus, beyond a band about its surface and on");
    out += comment(
      " its own side, its signed distance mdist_KEY(x), sampled (frepkit morph writes each as");
    out += comment(" STEM-KEY-distance.vti: load this with --shape mdist_KEY=that file).");
  }
  if (placement == KeyPlacement::Library)
  {
    out += comment(" The keys stay in their files: load this with each as a HyperFun library:");
    std::set<std::string> listed;
    for (const KeyObject& key : keys)
      if (listed.insert(key.file).second)
        out += comment("   --library " + key.file);
  }
  return out;
}

// Each key file's text from its first object to its end, in first-use order.
std::string pasted_keys(const std::vector<KeyFile>& files, std::vector<Diagnostic>& diagnostics)
{
  std::string out;
  for (const KeyFile& file : files)
  {
    std::ifstream in(file.path, std::ios::binary);
    if (!in.is_open())
    {
      diagnostics.push_back(error(file.path, {}, "cannot read the key file again"));
      return {};
    }
    const std::string text{ std::istreambuf_iterator<char>(in), {} };
    std::size_t start = 0; // the first object's line
    for (int line = 1; line < file.first_line; ++line)
    {
      const std::size_t end_of_line = text.find('\n', start);
      if (end_of_line == std::string::npos)
      {
        start = text.size();
        break;
      }
      start = end_of_line + 1;
    }
    std::string body = text.substr(start);
    while (!body.empty() && (body.back() == '\n' || body.back() == '\r' || body.back() == ' '))
      body.pop_back();
    out += "-- " + std::string(94, '=') + "\n-- verbatim from " + file.path +
           " (from its first object)\n" + body + "\n\n";
  }
  return out;
}

// What `measure` says of each key's compiled tape, measured once per distinct key object; a
// failure (its message) becomes a diagnostic "the key's <what>: ...".
template<typename Result, typename Measure>
bool measure_keys(const MorphSpec& spec,
  const std::vector<KeyFile>& files,
  const LoadOptions& key_options,
  const std::string& what,
  Measure measure,
  std::vector<Result>& results,
  std::vector<Diagnostic>& diagnostics)
{
  std::map<std::pair<std::string, std::string>, Result> measured;
  for (const Key& key : spec.keys)
  {
    const auto id = std::make_pair(key.file, lower_case(key.object));
    auto found = measured.find(id);
    if (found == measured.end())
    {
      const auto file = std::find_if(
        files.begin(), files.end(), [&](const KeyFile& f) { return f.path == key.file; });
      LoadOptions options = key_options; // its compile options
      options.object = key.object;
      const LoadedModel loaded = compile_object(file->program, options);
      Result result;
      if (loaded.ok())
        result = measure(loaded.model->tape());
      else
        result.error = loaded.message();
      if (!result.ok())
        diagnostics.push_back(error(key.file, {}, "the key's " + what + ": " + result.error));
      found = measured.emplace(id, std::move(result)).first;
    }
    results.push_back(found->second);
  }
  return diagnostics.empty();
}

// The keys' sampled distances as the functions the text calls (one per distinct key object).
void add_distances(const std::vector<KeyObject>& keys,
  const std::vector<KeyDistance>& distances,
  MorphText& result,
  std::vector<weight_text::KeyNormal>& normals)
{
  auto registry = std::make_shared<UserFunctionRegistry>();
  for (std::size_t k = 0; k < keys.size(); ++k)
  {
    const std::string function = "mdist_" + keys[k].name;
    normals.push_back({ function, distances[k].band });
    if (registry->find(function))
      continue;
    auto field = shapes::VolumeField::build(distances[k].grid, 0.0);
    if (!field.field)
    {
      result.diagnostics.push_back(error(keys[k].file, {}, "the key's distance: " + field.error));
      continue;
    }
    const std::string added = registry->add(shapes::volume_function(function, field.field));
    if (!added.empty())
      result.diagnostics.push_back(error(keys[k].file, {}, added));
    result.distances.push_back({ function, keys[k].name, distances[k].grid });
  }
  result.functions = std::move(registry);
}

} // namespace

MorphText write_morph(const MorphSpec& spec, KeyPlacement placement, const LoadOptions& key_options)
{
  MorphText result;
  if (!check_spec(spec, result.diagnostics))
    return result;
  std::vector<KeyObject> keys;
  std::vector<KeyFile> files;
  if (!read_keys(spec, key_options, keys, files, result.diagnostics) ||
      !check_keys(spec, keys, files, result.diagnostics))
    return result;
  std::vector<std::string> key_names;
  for (const KeyObject& key : keys)
    key_names.push_back(key.name);
  const std::vector<std::string> key_weights = detail::key_weight_expressions(
    spec, key_names, keys.front().x_dim, keys.front().a_dim, key_options, result.diagnostics);
  if (!result.ok())
    return result;
  std::vector<KeyFrame> frames;
  if (spec.alignment != Alignment::None &&
      !measure_keys(
        spec,
        files,
        key_options,
        "centroid and size",
        [&](const auto& tape) { return measure_key_frame(tape, spec.frame_samples); },
        frames,
        result.diagnostics))
    return result;
  std::vector<KeyDistance> distances;
  std::vector<weight_text::KeyNormal> normals;
  if (spec.normalisation == Normalisation::Distance)
  {
    if (!measure_keys(
          spec,
          files,
          key_options,
          "distance",
          [&](const auto& tape) { return measure_key_distance(tape, spec.distance_samples); },
          distances,
          result.diagnostics))
      return result;
    add_distances(keys, distances, result, normals);
    if (!result.ok())
      return result;
  }
  const int d = keys.front().x_dim;
  const int a_dim = keys.front().a_dim;
  result.x_dim = d + static_cast<int>(spec.lattice.size());
  std::string text = header(spec, keys, d, placement) + "\n";
  if (placement == KeyPlacement::Pasted)
  {
    text += pasted_keys(files, result.diagnostics);
    if (!result.ok())
      return result;
    text += "-- " + std::string(94, '=') + "\n";
  }
  else
  {
    for (const KeyFile& file : files)
      result.libraries.push_back(file.path);
  }
  const std::string name = lower_case(spec.name);
  const std::string head =
    "(x[" + std::to_string(result.x_dim) + "], a[" + std::to_string(a_dim) + "])";
  weight_text::Body body;
  body.name = name;
  body.d = d;
  body.lattice = spec.lattice;
  body.scheme = spec.scheme;
  body.timing = spec.timing;
  body.keys = key_names;
  body.alignment = spec.alignment;
  body.frames = frames;
  body.normals = normals;
  body.key_weights = key_weights;
  text += "-- the metamorphosis\n" + name + head + "\n{\n" + weight_text::body(body) + "}\n";
  if (name != "my_model")
  {
    text += "\n-- the default object (hfp and frepkit evaluate my_model when no object is named)\n"
            "my_model" +
            head + "\n{\n  my_model = " + name + "(x, a);\n}\n";
  }
  result.text = std::move(text);
  return result;
}

} // namespace frep::morph
