// produce: the phases in order (detail/phases.h), their failures and stops turned into the
// report.
#include "Production/detail/phases.h"

#include "Durable/output_error.h"
#include "Imaging/png_writer.h"

namespace frep::mapping
{
namespace production
{
namespace
{

// The products in order, once the plan is made; throws ProductionError or Stopped.
void make_products(Job& job, ProductionReport& report)
{
  const auto start = Clock::now();
  const Products products = choose_products(job);
  prepare_directory(job.options.directory);
  const int workers_count = worker_count(job.options);
  Record record;
  frame_solids(job, products, workers_count, record);
  Workers workers(job, products, workers_count);
  if (const std::string& font_error = workers.kit(0)->font_error; !font_error.empty())
  {
    report.warnings.push_back(font_error + "; pictures without labels");
  }
  const fs::path& out = job.options.directory;
  if (products.spreadsheet)
  {
    render_spreadsheet(job, workers, record);
  }
  if (products.shape)
  {
    render_shape(job, workers, record);
  }
  if (products.path)
  {
    draw_path(job, workers, record);
  }
  FrameFiles frames;
  frames.directory = out / "frames";
  if (products.frames)
  {
    render_frames(job, workers, frames, record);
  }
  if (products.ghost)
  {
    render_ghost(job, workers, record);
  }
  if (products.topology)
  {
    map_topology(job, workers, record);
  }
  const fs::path wav = out / (job.options.stem + ".wav");
  // The sound and the movie are put in place by the Media library: none is started after a stop.
  if (products.audio)
  {
    job.throw_if_stopped();
    write_sound(job, wav, record);
  }
  if (products.movie)
  {
    job.throw_if_stopped();
    const fs::path movie = out / (job.options.stem + ".mp4");
    encode_movie(job, workers, frames, products.audio ? &wav : nullptr, movie, record);
  }
  report.manifest = manifest_text(job, record);
  if (job.options.write_manifest)
  {
    write_text_file(out / "manifest.json", report.manifest);
  }
  workers.finish();
  report.stages = std::move(record.stages);
  report.triangles = workers.triangles();
  report.failed_samples = workers.failed_samples();
  report.seconds = seconds_since(start);
}

} // namespace
} // namespace production

const std::vector<std::string>& product_names()
{
  static const std::vector<std::string> names{ "spreadsheet", "path", "frames", "audio", "movie",
    "shape", "ghost", "topology" };
  return names;
}

std::string mapped_object(const Spec& spec, const std::string& requested)
{
  return requested.empty() ? spec.object : requested;
}

ProductionReport produce(const ProductionInputs& inputs, const ProductionOptions& options)
{
  using namespace production;
  ProductionReport report;
  if (!inputs.model)
  {
    report.error = "no model to map";
    return report;
  }
  Job job{ inputs, options, {}, {}, {}, {} };
  if (!plan_job(job, report.diagnostics))
  {
    report.status = ProductionReport::Status::Invalid;
    report.error = "the mapping does not fit " + inputs.model->name() + " (" +
                   std::to_string(inputs.model->x_dim()) + "-D); nothing written";
    return report;
  }
  try
  {
    make_products(job, report);
    report.status = ProductionReport::Status::Done;
  }
  catch (const Stopped&)
  {
    report.status = ProductionReport::Status::Cancelled;
    report.error = "cancelled; the files written so far are kept";
  }
  catch (const durable::Interrupted&)
  {
    report.status = ProductionReport::Status::Cancelled;
    report.error = "interrupted; the files written so far are kept";
  }
  catch (const ProductionError& e)
  {
    report.error = e.what();
  }
  catch (const durable::OutputError& e)
  {
    report.error = e.what();
  }
  catch (const imaging::PngError& e)
  {
    report.error = e.what();
  }
  // A stop that arrives while a phase fails for it (a write refused after a signal) is a stop.
  if (!report.ok() && job.stopped())
  {
    report.status = ProductionReport::Status::Cancelled;
  }
  return report;
}

} // namespace frep::mapping
