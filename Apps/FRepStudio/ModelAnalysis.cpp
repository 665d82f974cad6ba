#include "ModelAnalysis.h"

#include "Compiler/load_model.h"

#include <chrono>

namespace frepstudio
{

ModelAnalysis analyse_model(const std::string& text, const std::string& file_name,
  std::uint64_t generation, const frep::LoadOptions& options)
{
  const auto start = std::chrono::steady_clock::now();
  ModelAnalysis analysis;
  analysis.generation = generation;
  analysis.file_name = file_name;
  analysis.ranges = CoordinateRanges::from_model_text(text);

  // The engine's loading call, as every tool uses it: .vm by the name's extension, the libraries.
  frep::LoadedProgram parsed =
    frep::load_program(frep::ModelSource::from_text(text, file_name), options);
  analysis.diagnostics = std::move(parsed.diagnostics);
  if (parsed.ok())
  {
    analysis.program = parsed.program;
    const auto& objects = parsed.program->objects;
    for (int i = 0; i < static_cast<int>(objects.size()); ++i)
    {
      ObjectSummary summary;
      summary.name = objects[i].name;
      summary.x_dim = objects[i].x_dim;
      summary.a_dim = objects[i].a_dim;
      summary.s_dim = objects[i].s_dim;
      frep::Model::CompileResult compiled = frep::Model::compile(parsed.program, i);
      summary.model = compiled.model;
      for (auto& diagnostic : compiled.diagnostics)
        analysis.diagnostics.push_back(std::move(diagnostic));
      analysis.objects.push_back(std::move(summary));
    }
    analysis.default_object = frep::ast::select_default_object(*parsed.program);
  }
  analysis.seconds =
    std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return analysis;
}

} // namespace frepstudio
