// Background ray casting of the 3-D view's "High quality" picture (SectionPicture.h). As with
// MeshWorker, every request gets a generation number and a newer request (or cancel()) stops the
// older one at the ray caster's next tile; only the newest picture comes back, on the UI thread.
#pragma once

#include "SectionPicture.h"

#include <QImage>
#include <QObject>
#include <QThreadPool>

#include <atomic>
#include <cstdint>

namespace frepstudio
{

class PictureWorker : public QObject
{
  Q_OBJECT
public:
  explicit PictureWorker(QObject* parent = nullptr);
  /// Cancels what is running and waits for it to stop.
  ~PictureWorker() override;

  std::uint64_t request(SectionPictureRequest request);
  void cancel();
  /// True while the newest request's picture has not been delivered yet.
  bool busy() const { return pending_.load() != 0; }

signals:
  /// The newest request's picture (null when the section cannot be drawn) and its time.
  void pictureReady(quint64 generation, const QImage& picture, double seconds);

private:
  bool current(std::uint64_t generation) const { return latest_.load() == generation; }

  std::atomic<std::uint64_t> latest_{ 0 };
  std::atomic<int> pending_{ 0 };
  QThreadPool jobs_; // one job at a time; the ray caster's own threads use every core
};

} // namespace frepstudio
