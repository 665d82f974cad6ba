// A tape: straight-line code over double slots, the contract between the compiler (which
// produces it from the expression DAG) and the evaluators (point, batch, interval, gradient).
// A tape is immutable once built and is shared between threads; evaluators keep their scratch
// per thread.
#pragma once

#include "Compiler/opcode.h"
#include "Language/function_table.h"
#include "Language/source_location.h"

#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <vector>

namespace frep
{

/// One instruction. Slots are indices into the evaluator's register file.
struct Instruction
{
  Opcode op = Opcode::Const;
  std::uint32_t out = 0;
  std::uint32_t a = 0;
  std::uint32_t b = 0;
  std::uint32_t c = 0;
  std::int32_t index = 0; ///< Input index, HfPowInt exponent, ErrorIf error id, Call site
  double imm = 0;         ///< Const value
};

/// A run-time error the tape can raise, with the source position the original reports.
struct TapeError
{
  std::string message;
  SourceLocation location;
  /// The program file `location` refers to (empty: unknown). A composed model's tape holds the
  /// errors of several programs. (Initialised so that {message, location} stays complete.)
  std::string file{};
};

/// Interface of an opaque function evaluated one point at a time. It is shared by threads:
/// evaluate() is const; per-thread state lives in a Scratch the evaluator creates once.
class OpaqueFunction
{
public:
  struct Scratch
  {
    virtual ~Scratch() = default;
  };

  virtual ~OpaqueFunction() = default;
  /// Per-evaluator scratch (may be null when the function needs none).
  virtual std::unique_ptr<Scratch> make_scratch() const { return nullptr; }
  /// Computes outputs from inputs; returns 0 on success or a 1-based error id of the tape.
  virtual int evaluate(Scratch* scratch, std::span<const double> inputs,
    std::span<double> outputs) const = 0;

  // Optional forms (user functions provide them). The defaults say "not provided": the batch
  // evaluator then calls evaluate() per lane, the interval evaluator takes the whole line, the
  // gradient evaluator differences.

  /// Many points: input k of lane i is inputs[k][i]; writes outputs[j][i] and, for a lane that
  /// fails, errors[i] (lanes with errors[i] != 0 on entry have failed before: their outputs
  /// are ignored, their errors must be kept). Returns false when not provided.
  virtual bool evaluate_lanes(Scratch*, const double* const* /*inputs*/, int /*count*/,
    double* const* /*outputs*/, std::uint32_t* /*errors*/) const
  {
    return false;
  }
  /// An enclosure of the outputs over a box of inputs [lo[k], hi[k]]; sets may_fail when a point
  /// of the box may fail. Returns false when not provided (the whole line is used).
  virtual bool enclose(std::span<const double> /*lo*/, std::span<const double> /*hi*/,
    std::span<double> /*out_lo*/, std::span<double> /*out_hi*/, bool& /*may_fail*/) const
  {
    return false;
  }
  /// Whether evaluate_jacobian gives exact derivatives.
  virtual bool has_jacobian() const { return false; }
  /// Outputs and their derivatives by the inputs, jacobian[j * inputs.size() + k]; the status
  /// as evaluate(). Called only when has_jacobian().
  virtual int evaluate_jacobian(Scratch* scratch, std::span<const double> inputs,
    std::span<double> outputs, std::span<double> /*jacobian*/) const
  {
    return evaluate(scratch, inputs, outputs);
  }
};

struct CallSite
{
  std::shared_ptr<const OpaqueFunction> function;
  std::vector<std::uint32_t> inputs;  ///< slots read
  std::vector<std::uint32_t> outputs; ///< slots written
};

/// Straight-line program: inputs -> outputs. Output 0 is the object's value F; outputs
/// 1..s_dim are s[1..s_dim] after evaluation. A point whose evaluation raised an error has
/// error id > 0 and its outputs are meaningless (the evaluators return NaN for them).
struct Tape
{
  std::vector<Instruction> code;
  std::uint32_t slot_count = 0;
  std::uint32_t input_count = 0;           ///< free coordinates, in Input index order
  std::vector<std::uint32_t> outputs;      ///< output slots (value, s[1..])
  std::vector<TapeError> errors;           ///< errors[id - 1]
  std::vector<CallSite> calls;
  bool can_fail = false;                   ///< any ErrorIf or Call present

  /// Human-readable listing, one instruction per line.
  std::string dump() const;
};

} // namespace frep
