#include "PictureWorker.h"

#include <QMetaObject>

#include <chrono>

namespace frepstudio
{

PictureWorker::PictureWorker(QObject* parent)
  : QObject(parent)
{
  jobs_.setMaxThreadCount(1);
  jobs_.setExpiryTimeout(-1);
}

PictureWorker::~PictureWorker()
{
  cancel();
  jobs_.waitForDone();
}

std::uint64_t PictureWorker::request(SectionPictureRequest request)
{
  const std::uint64_t generation = latest_.fetch_add(1) + 1;
  pending_.store(1);
  jobs_.start([this, generation, request = std::move(request)] {
    if (!current(generation))
      return;
    const auto start = std::chrono::steady_clock::now();
    const QImage picture =
      section_picture(request, [this, generation] { return current(generation); });
    const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    QMetaObject::invokeMethod(this, [this, generation, picture, seconds] {
      if (!current(generation))
        return;
      pending_.store(0);
      emit pictureReady(generation, picture, seconds);
    }, Qt::QueuedConnection);
  });
  return generation;
}

void PictureWorker::cancel()
{
  latest_.fetch_add(1);
  pending_.store(0);
}

} // namespace frepstudio
