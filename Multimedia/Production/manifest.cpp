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
  if (!job.plan.projected.empty())
  {
    nlohmann::json projected = nlohmann::json::object();
    for (const ProjectedCoordinate& p : job.plan.projected)
    {
      projected[job.coordinates.names[static_cast<std::size_t>(p.coordinate)]] = {
        { "range", { p.range.lo, p.range.hi } }, { "tolerance", p.tolerance } };
    }
    manifest["projected"] = projected; // the sections are the union over these ranges
  }
  manifest["files"] = record.files;
  if (!record.topology.is_null())
  {
    manifest["topology"] = record.topology;
  }
  nlohmann::json timing = nlohmann::json::object();
  for (const auto& s : record.stages)
  {
    timing[s.name] = s.seconds;
  }
  manifest["seconds"] = timing;
  return manifest.dump(2) + "\n";
}

} // namespace frep::mapping::production
