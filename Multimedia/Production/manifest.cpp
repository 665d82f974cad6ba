// produce, phase 8: manifest.json.
#include "Production/detail/phases.h"

namespace frep::mapping::production
{

std::string manifest_text(const Job& job, const Record& record)
{
  nlohmann::json manifest{ { "model", job.inputs.model_label },
    { "mapping", job.inputs.mapping_label },
    { "object", job.model().name() },
    { "dimension", job.model().x_dim() } };
  manifest["files"] = record.files;
  nlohmann::json timing = nlohmann::json::object();
  for (const auto& s : record.stages)
  {
    timing[s.name] = s.seconds;
  }
  manifest["seconds"] = timing;
  return manifest.dump(2) + "\n";
}

} // namespace frep::mapping::production
