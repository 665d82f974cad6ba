// Fuzz harness (c): the mapping file loader and the planner (Multimedia/Mapping) on arbitrary text.
// Properties: load_mapping never throws and either succeeds or names at least one error, each
// with a message; a loaded spec saves and loads back to the same spec, as mapping_json.h
// promises; make_plan never throws, against a 3-D, a 4-D and a 6-D model, and reports errors
// with messages, or a plan whose frames and cells match what it says it has.
#include "Mapping/mapping_json.h"
#include "Mapping/mapping_plan.h"
#include "fuzz_check.h"

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <exception>
#include <string>

namespace
{

frep::mapping::ModelCoordinates model_of_dimension(int n)
{
  frep::mapping::ModelCoordinates model;
  for (int i = 1; i <= n; ++i)
  {
    model.names.push_back("x" + std::to_string(i));
    model.intervals.push_back({ -1.0, 1.0 });
  }
  return model;
}

void check_errors(const std::vector<frep::mapping::PlanError>& errors)
{
  for (const auto& e : errors)
  {
    FUZZ_CHECK(!e.message.empty(), "every error has a message");
  }
  FUZZ_CHECK(!frep::mapping::format_errors(errors).empty() || errors.empty(),
    "errors format");
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  const std::string text(reinterpret_cast<const char*>(data), size);
  try
  {
    const frep::mapping::LoadResult loaded = frep::mapping::load_mapping(text);
    check_errors(loaded.errors);
    if (!loaded.ok())
    {
      return 0;
    }
    const std::string saved = frep::mapping::save_mapping(loaded.spec);
    const frep::mapping::LoadResult reloaded = frep::mapping::load_mapping(saved);
    if (!reloaded.ok())
    {
      std::fprintf(stderr, "%s\n%s\n", saved.c_str(),
        frep::mapping::format_errors(reloaded.errors).c_str());
    }
    FUZZ_CHECK(reloaded.ok(), "a saved spec loads");
    FUZZ_CHECK(reloaded.spec == loaded.spec, "load(save(spec)) == spec");
    for (const int n : { 3, 4, 6 })
    {
      const frep::mapping::PlanResult planned =
        frep::mapping::make_plan(loaded.spec, model_of_dimension(n));
      check_errors(planned.errors);
      if (planned.ok())
      {
        const auto& shape = planned.plan.grid_shape;
        if (shape[0] > 0 || shape[1] > 0 || shape[2] > 0)
        {
          const std::size_t expected_cells = static_cast<std::size_t>(std::max(shape[0], 1)) *
            static_cast<std::size_t>(std::max(shape[1], 1)) *
            static_cast<std::size_t>(std::max(shape[2], 1));
          FUZZ_CHECK(planned.plan.cells.size() == expected_cells,
            "the plan has one cell per spreadsheet position");
        }
      }
    }
  }
  catch (const std::exception& e)
  {
    std::fprintf(stderr, "exception: %s\n", e.what());
    FUZZ_CHECK(false, "the loader and the planner never throw");
  }
  return 0;
}
