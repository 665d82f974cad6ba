// Model: compile() validates the object and lowers its default specialisation once (for
// is_compiled/node_count and a cached default tape); specialise() lowers again with the given
// constants, because folding parameters and fixed coordinates is what makes slices small.
// Lowering is linear in the executed program (unrolled loops count once per iteration).
//
// Compiled tapes evaluate every point from a fresh state (the conformance "fresh" mode): a[] as
// given, s[] = 0, locals unset. hfp's persistence of a[]/s[] between points is reproduced only
// by the Interpreter.
#include "Compiler/model.h"

#include "Compiler/emit.h"
#include "Compiler/library_call.h"
#include "Compiler/lower.h"
#include "Eval/ast_validation.h"

#include <stdexcept>

namespace frep
{

struct Model::Impl
{
  std::shared_ptr<const ast::Program> program;
  int object_index = 0;
  CompileOptions options;
  const ast::Object* object = nullptr;
  bool compiled = true;
  std::string fallback_reason;
  std::size_t node_count = 0;
  std::shared_ptr<const Tape> default_tape;

  /// Lowers and emits; falls back to the interpreter when the object cannot be lowered.
  /// `reason` receives the fallback reason (empty when compiled), `nodes` the DAG size.
  std::shared_ptr<const Tape> build(const Specialisation& spec,
    std::string& reason,
    std::size_t& nodes) const
  {
    try
    {
      compiler::Lowered lowered(options.max_nodes);
      compiler::lower(*program, object_index, spec, options, lowered);
      nodes = lowered.dag.size();
      reason.clear();
      return compiler::emit(lowered);
    }
    catch (const compiler::CannotCompile& e)
    {
      reason = e.what();
    }
    catch (const compiler::DagTooLarge& e)
    {
      reason = e.what();
    }
    nodes = 0;
    return fallback(spec);
  }

  std::shared_ptr<const Tape> fallback(const Specialisation& spec) const
  {
    auto tape = std::make_shared<Tape>();
    tape->errors = compiler::possible_errors(*program, object_index);
    tape->errors.push_back(TapeError{ "Run-time error", object->location });
    const int unknown = static_cast<int>(tape->errors.size());
    std::vector<double> parameters(static_cast<std::size_t>(object->a_dim), 0.0);
    for (std::size_t k = 0; k < parameters.size() && k < spec.parameters.size(); ++k)
    {
      parameters[k] = spec.parameters[k];
    }
    CallSite site;
    site.function = compiler::make_interpreter_function(
      program, object_index, std::move(parameters), tape->errors, unknown);
    const std::vector<int> inputs = compiler::input_indices(object->x_dim, spec);
    std::uint32_t slot = 0;
    for (int i = 0; i < object->x_dim; ++i)
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
    for (int k = 0; k <= object->s_dim; ++k)
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
};

Model::Model(std::unique_ptr<Impl> impl)
  : impl_(std::move(impl))
{
}

Model::~Model() = default;

Model::CompileResult Model::compile(std::shared_ptr<const ast::Program> program,
  int object_index,
  const CompileOptions& options)
{
  CompileResult result;
  auto fail = [&](std::string message, SourceLocation at = {})
  {
    result.diagnostics.push_back(
      Diagnostic{ program ? program->file : std::string(), at, std::move(message) });
    return result;
  };
  if (!program)
  {
    return fail("no program to compile");
  }
  if (object_index < 0 || static_cast<std::size_t>(object_index) >= program->objects.size())
  {
    return fail("object index " + std::to_string(object_index) + " is not an object of the file");
  }
  const ast::Object& object = program->objects[static_cast<std::size_t>(object_index)];
  try
  {
    eval::validate_object_graph(*program, object_index);
  }
  catch (const std::exception& e)
  {
    return fail(std::string("malformed program: ") + e.what(), object.location);
  }
  auto impl = std::make_unique<Impl>();
  impl->program = program;
  impl->object_index = object_index;
  impl->options = options;
  impl->object = &object;
  impl->default_tape = impl->build(Specialisation{}, impl->fallback_reason, impl->node_count);
  impl->compiled = impl->fallback_reason.empty();
  result.model = std::shared_ptr<const Model>(new Model(std::move(impl)));
  return result;
}

const std::string& Model::name() const
{
  return impl_->object->name;
}
int Model::x_dim() const
{
  return impl_->object->x_dim;
}
int Model::a_dim() const
{
  return impl_->object->a_dim;
}
int Model::s_dim() const
{
  return impl_->object->s_dim;
}
std::shared_ptr<const ast::Program> Model::program() const
{
  return impl_->program;
}
int Model::object_index() const
{
  return impl_->object_index;
}
bool Model::is_compiled() const
{
  return impl_->compiled;
}
const std::string& Model::fallback_reason() const
{
  return impl_->fallback_reason;
}
std::size_t Model::node_count() const
{
  return impl_->node_count;
}

std::shared_ptr<const Tape> Model::specialise(const Specialisation& specialisation) const
{
  const int x_dim = impl_->object->x_dim;
  if (specialisation.fixed.size() > static_cast<std::size_t>(x_dim))
  {
    throw std::invalid_argument("Model::specialise: more fixed coordinates than x_dim");
  }
  if (!specialisation.input_order.empty())
  {
    std::vector<bool> seen(static_cast<std::size_t>(x_dim), false);
    std::size_t free_count = 0;
    for (int i = 0; i < x_dim; ++i)
    {
      const auto k = static_cast<std::size_t>(i);
      free_count += (k >= specialisation.fixed.size() || !specialisation.fixed[k]) ? 1 : 0;
    }
    if (specialisation.input_order.size() != free_count)
    {
      throw std::invalid_argument("Model::specialise: input_order must list every free coordinate");
    }
    for (int i : specialisation.input_order)
    {
      const auto k = static_cast<std::size_t>(i);
      if (i < 0 || i >= x_dim || seen[k] ||
          (k < specialisation.fixed.size() && specialisation.fixed[k]))
      {
        throw std::invalid_argument(
          "Model::specialise: input_order holds a fixed, repeated or out-of-range coordinate");
      }
      seen[k] = true;
    }
  }
  std::string reason;
  std::size_t nodes = 0;
  return impl_->build(specialisation, reason, nodes);
}

std::shared_ptr<const Tape> Model::tape(std::span<const double> parameters) const
{
  if (parameters.empty())
  {
    return impl_->default_tape;
  }
  Specialisation spec;
  spec.parameters.assign(parameters.begin(), parameters.end());
  return specialise(spec);
}

} // namespace frep
