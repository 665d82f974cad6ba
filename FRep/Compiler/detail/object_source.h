// The tapes of one object of a HyperFun program: lowered for each specialisation (folding the
// fixed coordinates and a[] is what makes slices small), or, when the object cannot be lowered,
// one opaque call to the reference interpreter.
#pragma once

#include "Compiler/detail/model_impl.h"
#include "Language/ast.h"

#include <memory>

namespace frep::compiler
{

class ObjectSource final : public TapeSource
{
public:
  /// program.objects[object_index] must exist and have passed validation.
  ObjectSource(std::shared_ptr<const ast::Program> program,
    int object_index,
    const CompileOptions& options);

  Built build(const Specialisation& specialisation) const override;

private:
  std::shared_ptr<const Tape> fallback(const Specialisation& specialisation) const;

  std::shared_ptr<const ast::Program> program_;
  int object_index_ = 0;
  CompileOptions options_;
  const ast::Object* object_ = nullptr;
};

} // namespace frep::compiler
