// Background meshing of the current cross-section. A request is a list of resolutions (coarse
// first, then refined); every request gets a generation number, and a newer request cancels the
// older one through the mesher's progress callback. Results come back on the UI thread, only
// for the newest request, so the UI never waits for a mesh and never shows a stale one.
#pragma once

#include "SectionMeshConversion.h"
#include "SectionSpec.h"

#include "Compiler/model.h"

#include <QObject>
#include <QString>
#include <QThreadPool>

#include <array>
#include <atomic>
#include <chrono>
#include <cstdint>
#include <memory>
#include <vector>

namespace frep
{
class ThreadPool;
}

namespace frepstudio
{

struct SectionRequest : SectionSpec
{
  std::vector<int> resolutions; ///< samples per axis, in the order they are computed
};

struct SectionMesh
{
  std::uint64_t generation = 0;
  int resolution = 0;
  bool last_of_request = false; ///< the refined mesh (no further resolution follows)
  vtkSmartPointer<vtkPolyData> poly_data;
  std::size_t cells = 0;
  double seconds = 0; ///< specialise + extract + convert for this resolution
  std::array<double, 3> lo{};
  std::array<double, 3> hi{};
  std::chrono::steady_clock::time_point requested_at;
};

class MeshWorker : public QObject
{
  Q_OBJECT
public:
  explicit MeshWorker(QObject* parent = nullptr);
  /// Cancels what is running and waits for it to stop (a few ms: the mesher checks often).
  ~MeshWorker() override;

  /// Starts a request; returns its generation. Older requests stop at their next progress call.
  std::uint64_t request(SectionRequest request);
  /// Cancels everything (e.g. the model became invalid).
  void cancel();

  std::uint64_t latestGeneration() const { return latest_.load(); }
  /// True while a request's last resolution has not been delivered yet.
  bool busy() const { return pending_.load() != 0; }

signals:
  void sectionReady(const frepstudio::SectionMesh& mesh);
  void sectionFailed(quint64 generation, const QString& message);

private:
  void run(std::uint64_t generation, const SectionRequest& request,
    std::chrono::steady_clock::time_point requested_at);
  bool current(std::uint64_t generation) const { return latest_.load() == generation; }

  std::atomic<std::uint64_t> latest_{ 0 };
  std::atomic<int> pending_{ 0 };
  // One job at a time (the old one unwinds before the new one starts); the mesher's own pool
  // gives every job all cores.
  QThreadPool jobs_;
  std::shared_ptr<frep::ThreadPool> engine_pool_;
};

} // namespace frepstudio
