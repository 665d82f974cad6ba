#include "MeshWorker.h"

#include "SectionTape.h"

#include "Eval/thread_pool.h"
#include "Mesh/surface.h"

#include <QMetaObject>

#include <optional>
#include <stdexcept>

namespace frepstudio
{

MeshWorker::MeshWorker(QObject* parent)
  : QObject(parent)
  , engine_pool_(std::make_shared<frep::ThreadPool>(0))
{
  jobs_.setMaxThreadCount(1);
  // Keep the job thread: a new thread per slider move would add its start-up to every request.
  jobs_.setExpiryTimeout(-1);
}

MeshWorker::~MeshWorker()
{
  cancel();
  jobs_.waitForDone();
}

std::uint64_t MeshWorker::request(SectionRequest request)
{
  const std::uint64_t generation = latest_.fetch_add(1) + 1;
  const auto requested_at = std::chrono::steady_clock::now();
  pending_.store(1);
  // The older job, if any, sees latest_ change at its next progress call and returns; the pool's
  // single thread then picks this one up.
  jobs_.start([this, generation, request = std::move(request), requested_at] {
    run(generation, request, requested_at);
  });
  return generation;
}

void MeshWorker::cancel()
{
  latest_.fetch_add(1);
  pending_.store(0);
}

void MeshWorker::run(std::uint64_t generation, const SectionRequest& request,
  std::chrono::steady_clock::time_point requested_at)
{
  if (!current(generation) || !request.model)
    return;
  auto fail = [this, generation](const QString& message) {
    QMetaObject::invokeMethod(this, [this, generation, message] {
      if (current(generation))
      {
        pending_.store(0);
        emit sectionFailed(generation, message);
      }
    }, Qt::QueuedConnection);
  };

  const int x_dim = request.model->x_dim();
  if (x_dim < 2)
  {
    fail(tr("FRepStudio shows 3-D and 2-D cross-sections; this object has x[%1]").arg(x_dim));
    return;
  }
  const auto start = std::chrono::steady_clock::now();
  std::shared_ptr<const frep::Tape> tape;
  try
  {
    tape = section_tape(*request.model, request.parameters, request.fixed_values);
  }
  catch (const std::exception& error)
  {
    fail(QString::fromStdString(error.what()));
    return;
  }
  const SectionColouring colouring = colouring_for(*tape, request.s_dim);
  double specialise_seconds =
    std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  for (std::size_t r = 0; r < request.resolutions.size(); ++r)
  {
    if (!current(generation))
      return;
    const auto mesh_start = std::chrono::steady_clock::now();
    const int resolution = request.resolutions[r];
    const std::array<std::int64_t, 3> samples{ resolution, resolution, resolution };
    const frep::GridSpec grid = frep::box_grid(
      std::span<const double>(request.lo.data(), x_dim >= 3 ? 3 : 2), request.hi, samples);
    frep::mesh::ExtractOptions options;
    options.pool = engine_pool_;
    options.progress = [this, generation](double) { return current(generation); };
    frep::mesh::ExtractResult result = x_dim >= 3
      ? frep::mesh::extract_surface(tape, grid, options)
      : frep::mesh::extract_contour(tape, grid, options);
    if (result.cancelled || !current(generation))
      return;
    if (!result.error.empty())
    {
      fail(QString::fromStdString(result.error));
      return;
    }
    SectionMesh mesh;
    mesh.generation = generation;
    mesh.resolution = resolution;
    mesh.last_of_request = r + 1 == request.resolutions.size();
    mesh.poly_data = to_poly_data(result.surface, colouring);
    mesh.cells = result.surface.cell_count();
    mesh.lo = request.lo;
    mesh.hi = request.hi;
    mesh.requested_at = requested_at;
    mesh.seconds = specialise_seconds +
      std::chrono::duration<double>(std::chrono::steady_clock::now() - mesh_start).count();
    specialise_seconds = 0;
    QMetaObject::invokeMethod(this, [this, mesh] {
      if (!current(mesh.generation))
        return;
      if (mesh.last_of_request)
        pending_.store(0);
      emit sectionReady(mesh);
    }, Qt::QueuedConnection);
  }
}

} // namespace frepstudio
