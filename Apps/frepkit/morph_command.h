// frepkit morph KEY.hf[:OBJECT] ... --lattice 2x2 -o OUT.hf: key shapes on a lattice of
// parameters written as one HyperFun model of higher dimension (the engine's Morph/morph_text.h).
#pragma once

#include "user_inputs.h"

#include <string>
#include <vector>

namespace CLI
{
class App;
}

namespace frepkit
{

struct MorphOptions
{
  UserInputs user; ///< the keys' own --library and --shape
  std::vector<std::string> keys; ///< FILE or FILE:OBJECT, in lattice order
  std::string lattice;           ///< "2x2", "5", "3x3x2"; empty: one axis of every key
  std::string scheme = "linear";
  std::string name = "morph";
  bool paste = false;
  std::string align = "none";
  std::string output;
};

CLI::App* add_morph_command(CLI::App& app, MorphOptions& options);

/// Returns the exit code (0 written; 1 with every diagnostic printed).
int run_morph(const MorphOptions& options);

} // namespace frepkit
