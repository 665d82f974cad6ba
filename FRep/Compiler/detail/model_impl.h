// Internal to the compiler: what a Model is made of. A model is a description (name, sizes)
// plus a TapeSource that builds its tapes; the source is an AST object (object_source.h) or an
// operation on two other models (combine.cpp). Model's public API is the same for both.
#pragma once

#include "Compiler/model.h"
#include "Compiler/tape.h"

#include <cstddef>
#include <memory>
#include <string>

namespace frep
{
namespace compiler
{

/// Where a model's tapes come from. Immutable and shared between threads: build() is const.
class TapeSource
{
public:
  struct Built
  {
    std::shared_ptr<const Tape> tape;
    std::string fallback_reason; ///< why the tape calls the interpreter (empty: compiled)
    std::size_t node_count = 0;  ///< DAG nodes the tape was emitted from
  };

  virtual ~TapeSource() = default;
  /// `specialisation` has been validated against the model's x_dim.
  virtual Built build(const Specialisation& specialisation) const = 0;
};

/// Why `specialisation` does not fit a model with `x_dim` coordinates, or "" when it does
/// (Model::specialise throws with this message; combine() returns it as a value).
std::string specialisation_error(int x_dim, const Specialisation& specialisation);

} // namespace compiler

struct Model::Impl
{
  std::string name;
  int x_dim = 0;
  int a_dim = 0;
  int s_dim = 0;
  /// Null / -1 for models that are not an AST object (composed models).
  std::shared_ptr<const ast::Program> program;
  int object_index = -1;
  std::unique_ptr<const compiler::TapeSource> source;

  // Of the default specialisation (every coordinate free, a[] = 0), built by make().
  bool compiled = true;
  std::string fallback_reason;
  std::size_t node_count = 0;
  std::shared_ptr<const Tape> default_tape;

  /// Builds the default specialisation and wraps the model (Model's constructor is private;
  /// this nested type is the one place that may call it).
  static std::shared_ptr<const Model> make(std::unique_ptr<Impl> impl);
};

} // namespace frep
