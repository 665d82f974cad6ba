// The 3-D view of the current cross-section: a QVTKOpenGLNativeWidget with the section's mesh,
// the outline of the meshed box and labelled axes (vtkCubeAxesActor). In "High quality" mode a
// ray-cast picture of the section at the same camera (PictureWorker) replaces the mesh as the
// renderer's background while the camera rests; any interaction shows the mesh again.
#pragma once

#include <QWidget>

#include <vtkNew.h>
#include <vtkSmartPointer.h>

#include "Imaging/camera.h"

#include <array>

class QVTKOpenGLNativeWidget;
class vtkActor;
class vtkCubeAxesActor;
class vtkGenericOpenGLRenderWindow;
class vtkImageData;
class vtkOutlineSource;
class vtkPolyData;
class vtkPolyDataMapper;
class vtkRenderer;
class vtkTexture;

namespace frepstudio
{

class SectionView : public QWidget
{
  Q_OBJECT
public:
  explicit SectionView(QWidget* parent = nullptr);
  ~SectionView() override;

  /// Shows `poly_data` (its "Colors" or "s1" scalars if any) in the box lo..hi. The camera is
  /// reset to the default direction when `reset_camera` (a new model or object); otherwise the
  /// user's direction is kept, and the camera is moved to fit the box when the box differs from
  /// the last one (an edit changed the solid's bounds), else not at all.
  void setSection(vtkPolyData* poly_data, const std::array<double, 3>& lo,
    const std::array<double, 3>& hi, bool reset_camera);
  /// Removes the section (the outline and axes stay).
  void clearSection();

  /// The section shown now (null when none).
  vtkPolyData* section() const { return shown_; }
  /// Cells (triangles or segments) shown now.
  long long cellCount() const;
  /// Renders now and returns the picture of the render window (for screenshots).
  QImage renderToImage();
  vtkGenericOpenGLRenderWindow* renderWindow() const;

  /// The view's camera as the headless renderers' camera (x1..x3 are the world).
  frep::imaging::Camera camera() const;
  /// The render window's size in device pixels (what a picture must have to fill it).
  QSize pixelSize() const;
  /// The background gradient's colours, bottom and top (what a picture's background must be).
  std::array<float, 3> backgroundBottom() const;
  std::array<float, 3> backgroundTop() const;
  /// Shows `picture` (drawn at camera() and pixelSize()) in place of the mesh and the outline;
  /// the axes stay. Cleared by showMesh(), setSection() and clearSection().
  void showPicture(const QImage& picture);
  void showMesh();
  bool showingPicture() const { return showing_picture_; }
  QVTKOpenGLNativeWidget* vtkWidget() const { return widget_; }

signals:
  /// The render window finished a frame (the section is on screen).
  void frameRendered();
  /// The user started moving the camera (mouse or wheel) / stopped.
  void interactionStarted();
  void interactionEnded();
  /// The view's size changed (a picture no longer fits it).
  void resized();

protected:
  void resizeEvent(QResizeEvent* event) override;

private:
  void resetCamera(const double bounds[6]);
  /// Fits `bounds` to the view along the camera's direction, as resetCamera does.
  void fitCamera(const double bounds[6]);
  /// Back to the gradient background and the outline (the caller sets the mesh's visibility).
  void dropPicture();

  QVTKOpenGLNativeWidget* widget_ = nullptr;
  vtkNew<vtkGenericOpenGLRenderWindow> window_;
  vtkNew<vtkRenderer> renderer_;
  vtkNew<vtkPolyDataMapper> mapper_;
  vtkNew<vtkActor> actor_;
  vtkNew<vtkOutlineSource> outline_;
  vtkNew<vtkPolyDataMapper> outline_mapper_;
  vtkNew<vtkActor> outline_actor_;
  vtkNew<vtkCubeAxesActor> axes_;
  vtkSmartPointer<vtkPolyData> shown_;
  vtkNew<vtkTexture> picture_texture_;
  bool showing_picture_ = false;
  std::array<double, 6> bounds_{}; ///< the box of the last setSection
};

} // namespace frepstudio
