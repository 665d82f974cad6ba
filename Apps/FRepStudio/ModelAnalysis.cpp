#include "ModelAnalysis.h"

#include "Compiler/load_model.h"

#include <algorithm>
#include <cctype>
#include <chrono>

namespace frepstudio
{

namespace
{
std::string lower_case(std::string text)
{
  std::transform(text.begin(),
    text.end(),
    text.begin(),
    [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return text;
}
}

ModelAnalysis analyse_model(const std::string& text,
  const std::string& file_name,
  std::uint64_t generation,
  const frep::LoadOptions& options,
  const std::string& shown_object)
{
  const auto start = std::chrono::steady_clock::now();
  ModelAnalysis analysis;
  analysis.generation = generation;
  analysis.file_name = file_name;
  analysis.file_ranges = CoordinateRanges::from_model_text(text);

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
      summary.ranges = analysis.file_ranges;
      for (auto& diagnostic : compiled.diagnostics)
        analysis.diagnostics.push_back(std::move(diagnostic));
      analysis.objects.push_back(std::move(summary));
    }
    analysis.default_object = frep::ast::select_default_object(*parsed.program);
  }
  // The box only for a text that will be shown (one with errors keeps the last good model), and
  // for the object the window will show.
  if (analysis.ok())
  {
    auto shown = std::find_if(analysis.objects.begin(),
      analysis.objects.end(),
      [name = lower_case(shown_object)](const ObjectSummary& o) { return o.name == name; });
    if (shown == analysis.objects.end() && analysis.default_object >= 0)
      shown = analysis.objects.begin() + analysis.default_object;
    if (shown != analysis.objects.end() && shown->model)
    {
      shown->ranges = analysis.file_ranges.with_solid_bounds(*shown->model);
      shown->searched = true;
    }
  }
  analysis.seconds =
    std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return analysis;
}

} // namespace frepstudio
