// frepkit map, phase 7: manifest.json and the summary.
#include "map_phases.h"

#include <cstdio>
#include <iostream>

namespace frepkit::map_run
{

void write_manifest(const MapOptions& options,
  const MapInputs& in,
  const fs::path& out_dir,
  const MapRecord& record)
{
  nlohmann::json manifest{ { "model", options.model },
    { "mapping", options.mapping },
    { "object", in.model->name() },
    { "dimension", in.model->x_dim() } };
  manifest["files"] = record.files;
  nlohmann::json timing = nlohmann::json::object();
  for (const auto& s : record.stages)
  {
    timing[s.name] = s.seconds;
  }
  manifest["seconds"] = timing;
  const std::string text = manifest.dump(2) + "\n";
  if (options.manifest_out != nullptr)
  {
    *options.manifest_out = text;
    return;
  }
  write_text_file(out_dir / "manifest.json", text);
}

void print_summary(const MapOptions& options,
  const MapInputs& in,
  const fs::path& out_dir,
  const MapRecord& record,
  const MapWorkers& workers,
  Clock::time_point start)
{
  if (!options.quiet)
  {
    std::cerr << "frepkit map: " << in.model->name() << " (" << in.model->x_dim() << "-D) -> "
              << out_dir.string() << "\n";
    for (const auto& s : record.stages)
    {
      char line[256];
      std::snprintf(
        line, sizeof line, "  %-12s %7.2f s  %s\n", s.name.c_str(), s.seconds, s.detail.c_str());
      std::cerr << line;
    }
    char line[128];
    std::snprintf(line,
      sizeof line,
      "  %-12s %7.2f s  %zu triangles meshed, manifest.json\n",
      "total",
      seconds_since(start),
      workers.triangles());
    std::cerr << line;
  }
  if (workers.failed_samples() > 0)
  {
    std::cerr << "frepkit: warning: " << workers.failed_samples()
              << " samples raised a run-time error (taken as outside)\n";
  }
}

} // namespace frepkit::map_run
