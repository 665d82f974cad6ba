// A compiled HyperFun object: the program's expression DAG for one object, immutable and shared
// between threads. Specialising it (fixing some coordinates, setting a[]) yields a Tape, the
// straight-line code every evaluator runs. This is how slices of n-D models are evaluated.
// A model can also be an operation on two other models (set operations, blends, the Cartesian
// product: combine.h); such a composed model has no program of its own but specialises and
// evaluates like any other.
#pragma once

#include "Compiler/tape.h"
#include "Language/ast.h"
#include "Language/diagnostic.h"

#include <cstddef>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace frep
{

struct CompileOptions
{
  /// Loop iterations the compiler unrolls (loops whose condition depends only on constants)
  /// before giving up and falling back to the interpreter for the whole object.
  std::size_t max_unrolled_iterations = 1'000'000;
  /// DAG size limit (nodes); beyond it the object falls back to the interpreter.
  std::size_t max_nodes = 20'000'000;
};

/// Which coordinates stay free and which are fixed, and the parameter values.
struct Specialisation
{
  /// a[1..a_dim]; missing values are 0, extra values are ignored.
  std::vector<double> parameters;
  /// One entry per coordinate x[1..x_dim] (may be shorter: missing = free); nullopt = free.
  std::vector<std::optional<double>> fixed;
  /// Optional order of the free coordinates as tape inputs (0-based x indices). Empty = the
  /// free coordinates in increasing order.
  std::vector<int> input_order;
};

class Model
{
public:
  struct CompileResult
  {
    std::shared_ptr<const Model> model;
    std::vector<Diagnostic> diagnostics; ///< why compilation failed (model is null then)
  };

  /// Compiles program.objects[object_index].
  static CompileResult compile(std::shared_ptr<const ast::Program> program, int object_index,
    const CompileOptions& options = {});

  /// The object's name; for a composed model the operation and the operands' names, e.g.
  /// "union(ball, box)".
  const std::string& name() const;
  int x_dim() const;
  int a_dim() const;
  int s_dim() const;
  /// The program the model was compiled from and the object's index in it; null and -1 for a
  /// composed model (combine.h), which is not one object of one program.
  std::shared_ptr<const ast::Program> program() const;
  int object_index() const;

  /// False when the object could not be turned into a DAG (e.g. a loop whose condition depends
  /// on x): its tapes then contain one opaque Call to the interpreter. This describes the default
  /// specialisation (all coordinates free, a[] = 0); specialise() decides again for its own
  /// constants (fixing the coordinate a loop depends on makes it compilable, and vice versa).
  /// A composed model is compiled when both operands' tapes are.
  bool is_compiled() const;
  /// Why the object is interpreted (empty when compiled).
  const std::string& fallback_reason() const;

  /// Number of DAG nodes of the default specialisation (for tests and reports; for a composed
  /// model, the nodes of the DAG its operands' tapes were joined in).
  std::size_t node_count() const;

  /// A tape with the given coordinates fixed and parameters set: the object is executed
  /// symbolically with these constants (cost linear in the executed program, unrolled loops
  /// included: a few microseconds for small models, under 1 ms for a 200-primitive union).
  /// Tapes evaluate every point from a fresh state (a[] as given, s[] = 0, locals unset); hfp's
  /// persistence of a[]/s[] between points is reproduced only by the Interpreter.
  /// Throws std::invalid_argument for inconsistent sizes (programming errors).
  std::shared_ptr<const Tape> specialise(const Specialisation& specialisation) const;

  /// Convenience: every coordinate free, parameters a.
  std::shared_ptr<const Tape> tape(std::span<const double> parameters = {}) const;

  ~Model();
  Model(const Model&) = delete;
  Model& operator=(const Model&) = delete;

  struct Impl; ///< internal (Compiler/detail/model_impl.h)

private:
  explicit Model(std::unique_ptr<Impl> impl);
  std::unique_ptr<Impl> impl_;
};

} // namespace frep
