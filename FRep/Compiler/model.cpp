// Model: a description (name, sizes) and a TapeSource (model_impl.h). make() builds the default
// specialisation once (for is_compiled/node_count and a cached default tape); specialise()
// builds again with the given constants, because folding parameters and fixed coordinates is
// what makes slices small.
#include "Compiler/model.h"

#include "Compiler/detail/model_impl.h"
#include "Compiler/detail/object_source.h"
#include "Semantics/detail/ast_validation.h"

#include <stdexcept>

namespace frep
{

namespace compiler
{

std::string specialisation_error(int x_dim, const Specialisation& specialisation)
{
  if (specialisation.fixed.size() > static_cast<std::size_t>(x_dim))
  {
    return "more fixed coordinates than x_dim";
  }
  if (specialisation.input_order.empty())
  {
    return {};
  }
  std::vector<bool> seen(static_cast<std::size_t>(x_dim), false);
  std::size_t free_count = 0;
  for (int i = 0; i < x_dim; ++i)
  {
    const auto k = static_cast<std::size_t>(i);
    free_count += (k >= specialisation.fixed.size() || !specialisation.fixed[k]) ? 1 : 0;
  }
  if (specialisation.input_order.size() != free_count)
  {
    return "input_order must list every free coordinate";
  }
  for (int i : specialisation.input_order)
  {
    const auto k = static_cast<std::size_t>(i);
    if (i < 0 || i >= x_dim || seen[k] ||
        (k < specialisation.fixed.size() && specialisation.fixed[k]))
    {
      return "input_order holds a fixed, repeated or out-of-range coordinate";
    }
    seen[k] = true;
  }
  return {};
}

} // namespace compiler

std::shared_ptr<const Model> Model::Impl::make(std::unique_ptr<Impl> impl)
{
  compiler::TapeSource::Built built = impl->source->build(Specialisation{});
  impl->default_tape = std::move(built.tape);
  impl->fallback_reason = std::move(built.fallback_reason);
  impl->compiled = impl->fallback_reason.empty();
  impl->node_count = built.node_count;
  return std::shared_ptr<const Model>(new Model(std::move(impl)));
}

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
    semantics::validate_object_graph(*program, object_index);
  }
  catch (const std::exception& e)
  {
    return fail(std::string("malformed program: ") + e.what(), object.location);
  }
  auto impl = std::make_unique<Impl>();
  impl->name = object.name;
  impl->x_dim = object.x_dim;
  impl->a_dim = object.a_dim;
  impl->s_dim = object.s_dim;
  impl->program = program;
  impl->object_index = object_index;
  impl->source = std::make_unique<compiler::ObjectSource>(program, object_index, options);
  result.model = Impl::make(std::move(impl));
  return result;
}

const std::string& Model::name() const
{
  return impl_->name;
}
int Model::x_dim() const
{
  return impl_->x_dim;
}
int Model::a_dim() const
{
  return impl_->a_dim;
}
int Model::s_dim() const
{
  return impl_->s_dim;
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
  const std::string error = compiler::specialisation_error(impl_->x_dim, specialisation);
  if (!error.empty())
  {
    throw std::invalid_argument("Model::specialise: " + error);
  }
  return impl_->source->build(specialisation).tape;
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
