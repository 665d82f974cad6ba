// frepkit morph KEY.hf[:OBJECT] ... --lattice 2x2 -o OUT.hf: key shapes on a lattice of
// parameters written as one HyperFun model of higher dimension (the engine's Morph/morph_text.h).
#pragma once

#include "Morph/morph_text.h"
#include "user_inputs.h"

#include <string>
#include <vector>

namespace CLI
{
class App;
}

namespace frepkit
{

/// How the keys are weighed as the blend proceeds: options shared by frepkit morph and demo.
struct BlendOptions
{
  std::string timing = "linear";        ///< Morph/timing.h's names ("ease", "hold:0.3", ...)
  std::vector<std::string> key_weights; ///< KEY=EXPRESSION, each once
};

/// --timing and --key-weight on `command`.
void add_blend_options(CLI::App& command, BlendOptions& options);

/// The blend options into `spec` (a UserError for a key weight without '=').
void apply_blend_options(const BlendOptions& options, frep::morph::MorphSpec& spec);

struct MorphOptions
{
  UserInputs user;               ///< the keys' own --library and --shape
  std::vector<std::string> keys; ///< FILE or FILE:OBJECT, in lattice order
  std::string lattice;           ///< "2x2", "5", "3x3x2"; empty: one axis of every key
  std::string scheme = "linear";
  std::string name = "morph";
  bool paste = false;
  std::string align = "none";
  std::string normalise = "none";
  BlendOptions blend;
  std::string output;
};

/// Refuses (UserError) a normalisation whose files this build can neither write nor read again:
/// the distances are .vti volumes, which need VTK. Called before any key is measured.
void require_normalisation_files(frep::morph::Normalisation normalisation);

/// The keys' sampled distances of `morph` (Normalisation::Distance) written beside `model` as
/// MODELSTEM-KEY-distance.vti (each put in place durably); returns the --shape arguments that
/// load the model again ("mdist_cat=/out/meta5d-cat-distance.vti"), none without distances.
/// A UserError when the build has no .vti writer.
std::vector<std::string> write_distances(const frep::morph::MorphText& morph,
  const std::string& model);

CLI::App* add_morph_command(CLI::App& app, MorphOptions& options);

/// Returns the exit code (0 written; 1 with every diagnostic printed).
int run_morph(const MorphOptions& options);

} // namespace frepkit
