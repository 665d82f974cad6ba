// The 3-D view of the current cross-section: a QVTKOpenGLNativeWidget with the section's mesh,
// the outline of the meshed box and labelled axes (vtkCubeAxesActor).
#pragma once

#include <QWidget>

#include <vtkNew.h>
#include <vtkSmartPointer.h>

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

namespace frepstudio
{

class SectionView : public QWidget
{
  Q_OBJECT
public:
  explicit SectionView(QWidget* parent = nullptr);
  ~SectionView() override;

  /// Shows `poly_data` (its "Colors" or "s1" scalars if any) in the box lo..hi. The camera is
  /// reset when `reset_camera` (a new model or box), otherwise the user's view is kept.
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
  QVTKOpenGLNativeWidget* vtkWidget() const { return widget_; }

signals:
  /// The render window finished a frame (the section is on screen).
  void frameRendered();

private:
  void resetCamera(const double bounds[6]);

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
};

} // namespace frepstudio
