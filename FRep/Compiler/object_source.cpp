// Lowering is linear in the executed program (unrolled loops count once per iteration).
//
// Compiled tapes evaluate every point from a fresh state (the conformance "fresh" mode): a[] as
// given, s[] = 0, locals unset. hfp's persistence of a[]/s[] between points is reproduced only
// by the Interpreter.
#include "Compiler/detail/object_source.h"

#include "Compiler/detail/emit.h"
#include "Compiler/detail/library_call.h"
#include "Compiler/detail/lower.h"

namespace frep::compiler
{

ObjectSource::ObjectSource(std::shared_ptr<const ast::Program> program,
  int object_index,
  const CompileOptions& options)
  : program_(std::move(program))
  , object_index_(object_index)
  , options_(options)
  , object_(&program_->objects[static_cast<std::size_t>(object_index)])
{
}

TapeSource::Built ObjectSource::build(const Specialisation& spec) const
{
  Built built;
  try
  {
    Lowered lowered(options_.max_nodes);
    lower(*program_, object_index_, spec, options_, lowered);
    built.node_count = lowered.dag.size();
    built.tape = emit(lowered);
    return built;
  }
  catch (const CannotCompile& e)
  {
    built.fallback_reason = e.what();
  }
  catch (const DagTooLarge& e)
  {
    built.fallback_reason = e.what();
  }
  built.tape = fallback(spec);
  return built;
}

std::shared_ptr<const Tape> ObjectSource::fallback(const Specialisation& spec) const
{
  auto tape = std::make_shared<Tape>();
  tape->errors = possible_errors(*program_, object_index_);
  tape->errors.push_back(TapeError{ "Run-time error", object_->location,
    object_->file.empty() ? program_->file : object_->file });
  const int unknown = static_cast<int>(tape->errors.size());
  std::vector<double> parameters(static_cast<std::size_t>(object_->a_dim), 0.0);
  for (std::size_t k = 0; k < parameters.size() && k < spec.parameters.size(); ++k)
  {
    parameters[k] = spec.parameters[k];
  }
  CallSite site;
  site.function = make_interpreter_function(
    program_, object_index_, std::move(parameters), tape->errors, unknown);
  const std::vector<int> inputs = input_indices(object_->x_dim, spec);
  std::uint32_t slot = 0;
  for (int i = 0; i < object_->x_dim; ++i)
  {
    Instruction ins;
    ins.out = slot;
    const auto k = static_cast<std::size_t>(i);
    if (inputs[k] >= 0)
    {
      ins.op = Opcode::Input;
      ins.index = inputs[k];
      ++tape->input_count;
    }
    else
    {
      ins.op = Opcode::Const;
      ins.imm = *spec.fixed[k];
    }
    tape->code.push_back(ins);
    site.inputs.push_back(slot++);
  }
  for (int k = 0; k <= object_->s_dim; ++k)
  {
    site.outputs.push_back(slot);
    tape->outputs.push_back(slot++);
  }
  Instruction call;
  call.op = Opcode::Call;
  call.index = 0;
  tape->code.push_back(call);
  tape->calls.push_back(std::move(site));
  tape->slot_count = slot;
  tape->can_fail = true;
  return tape;
}

} // namespace frep::compiler
