#include "SectionView.h"

#include "Imaging/camera.h"

#include <QImage>
#include <QResizeEvent>
#include <QVBoxLayout>
#include <QVTKOpenGLNativeWidget.h>

#include <vtkActor.h>
#include <vtkCallbackCommand.h>
#include <vtkCamera.h>
#include <vtkCubeAxesActor.h>
#include <vtkGenericOpenGLRenderWindow.h>
#include <vtkImageData.h>
#include <vtkInteractorStyleTrackballCamera.h>
#include <vtkMath.h>
#include <vtkOutlineSource.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderWindowInteractor.h>
#include <vtkRenderer.h>
#include <vtkTextProperty.h>
#include <vtkTexture.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>

namespace frepstudio
{

SectionView::SectionView(QWidget* parent)
  : QWidget(parent)
{
  widget_ = new QVTKOpenGLNativeWidget(this);
  // No multisampling: under Mesa's llvmpipe (Xvfb, remote desktops) an MSAA framebuffer
  // multiplies the cost of every frame, and interactive re-meshing renders often.
  window_->SetMultiSamples(0);
  widget_->setRenderWindow(window_);
  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(0, 0, 0, 0);
  layout->addWidget(widget_);

  renderer_->SetBackground(0.16, 0.17, 0.20);
  renderer_->SetBackground2(0.42, 0.45, 0.52);
  renderer_->GradientBackgroundOn();
  window_->AddRenderer(renderer_);

  // hfp's default face colour (50, 200, 80), used when the model has no s[] colours.
  actor_->GetProperty()->SetColor(50 / 255.0, 200 / 255.0, 80 / 255.0);
  actor_->GetProperty()->SetSpecular(0.3);
  actor_->GetProperty()->SetSpecularPower(30);
  actor_->GetProperty()->SetLineWidth(2);
  mapper_->ScalarVisibilityOff();
  actor_->SetMapper(mapper_);
  actor_->VisibilityOff();
  renderer_->AddActor(actor_);

  outline_mapper_->SetInputConnection(outline_->GetOutputPort());
  outline_actor_->SetMapper(outline_mapper_);
  outline_actor_->GetProperty()->SetColor(0.85, 0.85, 0.85);
  renderer_->AddActor(outline_actor_);

  axes_->SetCamera(renderer_->GetActiveCamera());
  axes_->SetXTitle("x1");
  axes_->SetYTitle("x2");
  axes_->SetZTitle("x3");
  axes_->SetFlyModeToOuterEdges();
  axes_->SetGridLineLocation(vtkCubeAxesActor::VTK_GRID_LINES_FURTHEST);
  for (int i = 0; i < 3; ++i)
  {
    axes_->GetTitleTextProperty(i)->SetColor(0.9, 0.9, 0.9);
    axes_->GetLabelTextProperty(i)->SetColor(0.9, 0.9, 0.9);
  }
  axes_->GetXAxesLinesProperty()->SetColor(0.8, 0.8, 0.8);
  axes_->GetYAxesLinesProperty()->SetColor(0.8, 0.8, 0.8);
  axes_->GetZAxesLinesProperty()->SetColor(0.8, 0.8, 0.8);
  renderer_->AddActor(axes_);

  const double bounds[6] = { -10, 10, -10, 10, -10, 10 };
  outline_->SetBounds(bounds);
  axes_->SetBounds(bounds);
  resetCamera(bounds);

  // frameSwapped is when a frame is really on screen (QVTKOpenGLNativeWidget renders in
  // paintGL, later than our Render() calls): what the interactive timings must measure.
  connect(widget_, &QOpenGLWidget::frameSwapped, this, &SectionView::frameRendered);

  // VTK's default trackball camera, set explicitly so that its start/end of interaction (mouse
  // drags and wheel steps alike) can be observed: the "High quality" picture follows them.
  vtkNew<vtkInteractorStyleTrackballCamera> style;
  window_->GetInteractor()->SetInteractorStyle(style);
  vtkNew<vtkCallbackCommand> started;
  started->SetClientData(this);
  started->SetCallback([](vtkObject*, unsigned long, void* view, void*) {
    emit static_cast<SectionView*>(view)->interactionStarted();
  });
  style->AddObserver(vtkCommand::StartInteractionEvent, started);
  vtkNew<vtkCallbackCommand> ended;
  ended->SetClientData(this);
  ended->SetCallback([](vtkObject*, unsigned long, void* view, void*) {
    emit static_cast<SectionView*>(view)->interactionEnded();
  });
  style->AddObserver(vtkCommand::EndInteractionEvent, ended);
  picture_texture_->InterpolateOff();
}

SectionView::~SectionView() = default;
void SectionView::setSection(vtkPolyData* poly_data, const std::array<double, 3>& lo,
  const std::array<double, 3>& hi, bool reset_camera)
{
  dropPicture();
  shown_ = poly_data;
  mapper_->SetInputData(poly_data);
  vtkDataArray* scalars = poly_data ? poly_data->GetPointData()->GetScalars() : nullptr;
  if (scalars && std::strcmp(scalars->GetName() ? scalars->GetName() : "", "Colors") == 0)
  {
    mapper_->ScalarVisibilityOn();
    mapper_->SetColorModeToDirectScalars();
  }
  else if (scalars)
  {
    mapper_->ScalarVisibilityOn();
    mapper_->SetColorModeToMapScalars();
    double range[2];
    scalars->GetRange(range);
    mapper_->SetScalarRange(range[0], range[1] > range[0] ? range[1] : range[0] + 1);
  }
  else
  {
    mapper_->ScalarVisibilityOff();
  }
  actor_->SetVisibility(poly_data != nullptr);

  const double bounds[6] = { lo[0], hi[0], lo[1], hi[1], lo[2], hi[2] };
  outline_->SetBounds(bounds);
  axes_->SetBounds(bounds);
  if (reset_camera)
    resetCamera(bounds);
  else if (!std::equal(bounds_.begin(), bounds_.end(), bounds))
    fitCamera(bounds);
  std::copy(bounds, bounds + 6, bounds_.begin());
  renderer_->ResetCameraClippingRange(bounds);
  // Outside paintGL this only asks QVTKOpenGLNativeWidget for a VTK render in its next paintGL
  // (a plain update() would only re-show the cached frame).
  window_->Render();
}

void SectionView::resetCamera(const double bounds[6])
{
  // From +x +y +z, y up: the HyperFun models (and hfp's views) have y as their vertical.
  vtkCamera* camera = renderer_->GetActiveCamera();
  camera->SetFocalPoint(0, 0, 0);
  camera->SetPosition(1, 0.8, 2.2);
  camera->SetViewUp(0, 1, 0);
  fitCamera(bounds);
}

void SectionView::fitCamera(const double bounds[6])
{
  // Along the camera's direction, as close as the box's eight corners allow (kFill of the view's
  // height and width, room for the axes' labels beside the box): closer than vtkRenderer's
  // ResetCamera, which fits the box's bounding sphere. The fit is the project's one
  // (imaging::fit_points, as the ray caster's and the mapping's cameras), for this view's own
  // direction, whose view axis may pass beside the box's centre where that lets the eye come
  // closer. A unit ball in its box: 0.461 of the height and 0.557 of the width of the test's view
  // (FRepStudio::viewFramesTheSolid prints them).
  vtkCamera* camera = renderer_->GetActiveCamera();
  camera->OrthogonalizeViewUp();
  frep::imaging::Camera direction;
  camera->GetPosition(direction.position.data());
  camera->GetFocalPoint(direction.focal_point.data());
  camera->GetViewUp(direction.view_up.data());
  std::array<frep::imaging::Vec3, 8> corners;
  for (int corner = 0; corner < 8; ++corner)
    for (int i = 0; i < 3; ++i)
      corners[corner][i] = bounds[2 * i + ((corner >> i) & 1)];
  frep::imaging::FitOptions options;
  options.view_angle_deg = 30;
  options.fill = 0.85;
  const QSize size = pixelSize();
  const double aspect =
    size.width() > 0 && size.height() > 0 ? double(size.width()) / size.height() : 1.0;
  const frep::imaging::Camera fitted =
    frep::imaging::fit_points(corners, aspect, direction, options);
  camera->SetViewAngle(fitted.view_angle_deg);
  camera->SetFocalPoint(fitted.focal_point.data());
  camera->SetPosition(fitted.position.data());
  renderer_->ResetCameraClippingRange(bounds);
}

void SectionView::clearSection()
{
  dropPicture();
  shown_ = nullptr;
  mapper_->SetInputData(nullptr);
  actor_->VisibilityOff();
  window_->Render();
}

long long SectionView::cellCount() const
{
  return shown_ ? static_cast<long long>(shown_->GetNumberOfCells()) : 0;
}

QImage SectionView::renderToImage()
{
  // QOpenGLWidget::grabFramebuffer() runs paintGL (VTK renders, ready for it there, unlike a
  // vtkWindowToImageFilter read-back outside paintGL) and reads the widget's framebuffer, so a
  // screenshot never depends on how the platform composites OpenGL widgets into
  // QWidget::grab().
  return widget_->grabFramebuffer().convertToFormat(QImage::Format_RGB888);
}

vtkGenericOpenGLRenderWindow* SectionView::renderWindow() const
{
  return window_;
}

frep::imaging::Camera SectionView::camera() const
{
  vtkCamera* vtk_camera = renderer_->GetActiveCamera();
  frep::imaging::Camera camera;
  vtk_camera->GetPosition(camera.position.data());
  vtk_camera->GetFocalPoint(camera.focal_point.data());
  vtk_camera->GetViewUp(camera.view_up.data());
  camera.view_angle_deg = vtk_camera->GetViewAngle();
  camera.orthographic = vtk_camera->GetParallelProjection() != 0;
  camera.parallel_scale = vtk_camera->GetParallelScale();
  return camera;
}

QSize SectionView::pixelSize() const
{
  const int* size = window_->GetSize();
  return size[0] > 0 && size[1] > 0 ? QSize(size[0], size[1])
                                    : widget_->size() * widget_->devicePixelRatioF();
}

std::array<float, 3> SectionView::backgroundBottom() const
{
  const double* c = renderer_->GetBackground();
  return { static_cast<float>(c[0]), static_cast<float>(c[1]), static_cast<float>(c[2]) };
}

std::array<float, 3> SectionView::backgroundTop() const
{
  const double* c = renderer_->GetBackground2();
  return { static_cast<float>(c[0]), static_cast<float>(c[1]), static_cast<float>(c[2]) };
}

void SectionView::showPicture(const QImage& picture)
{
  if (picture.isNull())
    return;
  // QImage's first row is the top; vtkImageData's first row is the bottom.
  const QImage rgb = picture.convertToFormat(QImage::Format_RGB888);
  vtkNew<vtkImageData> image;
  image->SetDimensions(rgb.width(), rgb.height(), 1);
  image->AllocateScalars(VTK_UNSIGNED_CHAR, 3);
  auto* pixels = static_cast<unsigned char*>(image->GetScalarPointer());
  const std::size_t row_bytes = static_cast<std::size_t>(rgb.width()) * 3;
  for (int y = 0; y < rgb.height(); ++y)
    std::memcpy(pixels + static_cast<std::size_t>(rgb.height() - 1 - y) * row_bytes,
      rgb.constScanLine(y), row_bytes);
  picture_texture_->SetInputData(image);
  renderer_->SetBackgroundTexture(picture_texture_);
  renderer_->TexturedBackgroundOn();
  actor_->VisibilityOff();
  outline_actor_->VisibilityOff(); // drawn over the picture it would cross the shape
  showing_picture_ = true;
  window_->Render();
}

void SectionView::dropPicture()
{
  showing_picture_ = false;
  renderer_->TexturedBackgroundOff();
  outline_actor_->VisibilityOn();
}

void SectionView::showMesh()
{
  if (!showing_picture_)
    return;
  dropPicture();
  actor_->SetVisibility(shown_ != nullptr);
  window_->Render();
}

void SectionView::resizeEvent(QResizeEvent* event)
{
  QWidget::resizeEvent(event);
  emit resized();
}

} // namespace frepstudio
