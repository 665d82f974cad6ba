#include "morph_command.h"

#include "Durable/atomic_output.h"
#include "Morph/morph_text.h"
#include "model_loading.h"
#include "section_writers/vti_writer.h"
#include "vtk_shape_reader.h"
#include "user_error.h"

#include <CLI/CLI.hpp>
#include <filesystem>

#include <iostream>
#include <sstream>

namespace frepkit
{
namespace
{

// "cat.hf:cat" -> {cat.hf, cat}; "cat.hf" -> {cat.hf, ""}. The part after the last ':' is an
// object only when it is a name (no '/', '.' or '\\'), so paths with ':' still work.
frep::morph::Key parse_key(const std::string& text)
{
  const std::size_t colon = text.rfind(':');
  if (colon != std::string::npos && colon + 1 < text.size() &&
      text.find_first_of("/.\\", colon + 1) == std::string::npos)
  {
    return { text.substr(0, colon), text.substr(colon + 1) };
  }
  return { text, std::string() };
}

// "2x2" -> {2, 2}; empty -> {keys}.
std::vector<int> parse_lattice(const std::string& text, std::size_t keys)
{
  if (text.empty())
    return { static_cast<int>(keys) };
  std::vector<int> lattice;
  std::stringstream in(text);
  std::string item;
  while (std::getline(in, item, 'x'))
  {
    std::size_t used = 0;
    int n = 0;
    try
    {
      n = std::stoi(item, &used);
    }
    catch (const std::exception&)
    {
      used = 0;
    }
    if (used == 0 || used != item.size())
      throw UserError("--lattice " + text + ": expected node counts joined by x, e.g. 2x2 or 5x5");
    lattice.push_back(n);
  }
  return lattice;
}

} // namespace

void require_normalisation_files(frep::morph::Normalisation normalisation)
{
  if (normalisation == frep::morph::Normalisation::Distance && !vtk_shapes_available())
  {
    throw UserError("--normalise distance needs a frepkit built with VTK (the keys' distances "
                    "are written and read as .vti volumes; FREPKIT_ENABLE_VTK is off)");
  }
}

std::vector<std::string> write_distances(const frep::morph::MorphText& morph,
  const std::string& model)
{
  std::vector<std::string> shapes;
  const std::filesystem::path path(model);
  for (const frep::morph::DistanceVolume& distance : morph.distances)
  {
    SampledSection volume;
    volume.axes = 3;
    for (std::size_t k = 0; k < 3; ++k)
    {
      volume.samples[k] = distance.grid.dims[k];
      volume.origin[k] = distance.grid.origin[k];
      volume.spacing[k] = distance.grid.spacing[k];
    }
    volume.values = distance.grid.values;
    const std::filesystem::path file =
      path.parent_path() / (path.stem().string() + "-" + distance.key + "-distance.vti");
    frep::durable::AtomicOutput out(file.string());
    write_vti(out.stream(), volume);
    out.commit();
    shapes.push_back(distance.function + "=" + file.string());
  }
  return shapes;
}

void add_blend_options(CLI::App& command, BlendOptions& options)
{
  command
    .add_option("--timing",
      options.timing,
      "How the blend moves between neighbouring keys: linear, ease (starts and stops gently at "
      "each key), ease-in, ease-out, or hold:H (each key shown alone for H/2 of the way on "
      "either side, 0 <= H < 1)")
    ->check(
      [](const std::string& name)
      {
        return frep::morph::timing_from_name(name)
                 ? std::string()
                 : "not a timing (linear, ease, ease-in, ease-out, hold:H with 0 <= H < 1)";
      })
    ->capture_default_str();
  command.add_option("--key-weight",
    options.key_weights,
    "KEY=EXPRESSION: how much the key (its object name) counts against the others: a number "
    "(globally), or a HyperFun expression of the point x[] (locally; mx[] is the point in the "
    "keys' space, for a field: vol(mx)). Weights are at least 0.001 and normalised; every key "
    "is still itself at its node. Repeatable; linear or b-spline only");
}

void apply_blend_options(const BlendOptions& options, frep::morph::MorphSpec& spec)
{
  spec.timing = *frep::morph::timing_from_name(options.timing);
  for (const std::string& weight : options.key_weights)
  {
    const std::size_t equals = weight.find('=');
    if (equals == std::string::npos || equals == 0 || equals + 1 == weight.size())
      throw UserError("--key-weight " + weight + ": give KEY=EXPRESSION, e.g. cat=2");
    spec.key_weights.push_back({ weight.substr(0, equals), weight.substr(equals + 1) });
  }
}

CLI::App* add_morph_command(CLI::App& app, MorphOptions& options)
{
  CLI::App* morph = app.add_subcommand("morph",
    "Write a metamorphosis: key shapes (HyperFun objects of the same coordinates) on a lattice "
    "of parameters, blended into one HyperFun model with the parameters as its last "
    "coordinates, each over [0, 1]. Linear on 2x2 is the paper's bilinear formula.");
  morph
    ->add_option("keys",
      options.keys,
      "Key shapes FILE.hf or FILE.hf:OBJECT in lattice order, the first parameter fastest "
      "(2x2: x4=0 x5=0, x4=1 x5=0, x4=0 x5=1, x4=1 x5=1)")
    ->required();
  morph->add_option("--lattice",
    options.lattice,
    "Nodes per parameter, e.g. 2x2 (two parameters) or 5 (one); default: one parameter over "
    "all keys");
  morph
    ->add_option("--scheme",
      options.scheme,
      "Weights: linear, catmull-rom (through every key, C1) or b-spline (smooth, C2: "
      "reaches the end keys only)")
    ->check(CLI::IsMember({ "linear", "catmull-rom", "b-spline" }))
    ->capture_default_str();
  morph->add_option("--name", options.name, "The object written (my_model calls it)")
    ->capture_default_str();
  morph
    ->add_option("--align",
      options.align,
      "Align the keys as the blend proceeds: none (the paper), centroid (each key travels "
      "with the blended centroid) or size (and is scaled to the blended size, its F alike)")
    ->check(CLI::IsMember({ "none", "centroid", "size" }))
    ->capture_default_str();
  morph
    ->add_option("--normalise",
      options.normalise,
      "Make the keys' values comparable: none (as they are) or distance (beyond a band about "
      "its surface each key gains its signed distance, sampled and written beside the model as "
      "STEM-KEY-distance.vti; the keys' zero sets are kept exactly)")
    ->check(CLI::IsMember({ "none", "distance" }))
    ->capture_default_str();
  add_blend_options(*morph, options.blend);
  morph->add_flag("--paste",
    options.paste,
    "Copy the keys' objects into the file (one file the original HyperFun reads); default: "
    "call them from their files, loaded with --library");
  morph->add_option("-o,--output", options.output, "The model file to write (- for stdout)")
    ->required();
  add_user_input_options(morph, options.user);
  return morph;
}

int run_morph(const MorphOptions& options)
{
  frep::morph::MorphSpec spec;
  for (const std::string& key : options.keys)
    spec.keys.push_back(parse_key(key));
  spec.lattice = parse_lattice(options.lattice, spec.keys.size());
  spec.scheme = *frep::morph::interpolation_from_name(options.scheme);
  spec.name = options.name;
  spec.alignment = *frep::morph::alignment_from_name(options.align);
  spec.normalisation = *frep::morph::normalisation_from_name(options.normalise);
  apply_blend_options(options.blend, spec);
  if (spec.normalisation != frep::morph::Normalisation::None && options.output == "-")
  {
    throw UserError(
      "--normalise distance writes the keys' distances beside the model: give -o FILE");
  }
  require_normalisation_files(spec.normalisation);
  const frep::morph::KeyPlacement placement =
    options.paste ? frep::morph::KeyPlacement::Pasted : frep::morph::KeyPlacement::Library;
  const frep::morph::MorphText morph =
    frep::morph::write_morph(spec, placement, load_options(options.user));
  if (!morph.ok())
  {
    std::cerr << frep::format_diagnostics(morph.diagnostics);
    throw UserError("morph: " + std::to_string(morph.diagnostics.size()) +
                    (morph.diagnostics.size() == 1 ? " error" : " errors") + ", nothing written");
  }
  const std::vector<std::string> shapes = write_distances(morph, options.output);
  frep::durable::AtomicOutput out(options.output);
  out.stream() << morph.text;
  out.commit();
  if (options.output != "-")
  {
    std::cerr << "frepkit: wrote " << options.output << ": " << spec.name << " of x[" << morph.x_dim
              << "] from " << spec.keys.size() << " keys";
    if (!morph.libraries.empty())
    {
      std::cerr << "; load it with";
      for (const std::string& library : morph.libraries)
        std::cerr << " --library " << library;
    }
    if (!shapes.empty())
    {
      std::cerr << (morph.libraries.empty() ? "; load it with" : "");
      for (const std::string& shape : shapes)
        std::cerr << " --shape " << shape;
    }
    std::cerr << '\n';
  }
  return 0;
}

} // namespace frepkit
