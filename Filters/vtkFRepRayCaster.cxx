#include "vtkFRepRayCaster.h"

#include "vtkFRepInformation.h"
#include "vtkFRepObject.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkUnsignedCharArray.h"

#include "Raycast/raycast.h"
#include "Raycast/shape_camera.h"
#include "Imaging/camera.h"
#include "Imaging/image.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <new>
#include <optional>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

vtkStandardNewMacro(vtkFRepRayCaster);

namespace
{
double Clamp01(double v)
{
  return std::isnan(v) ? 0.0 : std::clamp(v, 0.0, 1.0);
}

unsigned char ToByte(float v)
{
  const float c = std::isnan(v) ? 0.0F : std::clamp(v, 0.0F, 1.0F);
  return static_cast<unsigned char>(std::lround(255.0F * c));
}
}

// What RequestInformation decided, for RequestData: the picture's size and the box.
struct vtkFRepRayCaster::Internals
{
  bool Valid = false;
  int Width = 0;
  int Height = 0;
  double Box[6] = { 0, 0, 0, 0, 0, 0 }; // lo, hi per axis

  // The execution's camera and floor, once the tape is known (see Fit).
  frep::imaging::Camera Camera;
  std::optional<frep::raycast::Floor> Floor;
  void Fit(vtkFRepRayCaster& self, frep::raycast::Shape& shape);
};

// The camera frames the solid (FrameSolid) or the box, with the floor under the solid
// (raycast::frame_shape, shared with frepkit render); the shape keeps the solid's bounds so that
// rendering does not search again.
void vtkFRepRayCaster::Internals::Fit(vtkFRepRayCaster& self, frep::raycast::Shape& shape)
{
  frep::raycast::ShapeView view;
  view.azimuth_deg = self.Azimuth;
  view.elevation_deg = self.Elevation;
  view.aspect = static_cast<double>(this->Width) / this->Height;
  view.fit.view_angle_deg = self.ViewAngle;
  view.fit.orthographic = self.ParallelProjection != 0;
  view.frame_solid = self.FrameSolid != 0;
  view.floor = self.Floor != 0;
  view.threads = self.NumberOfThreads;
  frep::raycast::FramedShape framed = frep::raycast::frame_shape(shape, view);
  this->Camera = framed.camera;
  this->Floor = framed.floor;
  std::copy(this->Camera.position.begin(), this->Camera.position.end(), self.CameraPosition);
  std::copy(
    this->Camera.focal_point.begin(), this->Camera.focal_point.end(), self.CameraFocalPoint);
  const frep::imaging::CameraFrame frame = frep::imaging::camera_frame(this->Camera);
  std::copy(frame.up.begin(), frame.up.end(), self.CameraViewUp);
  self.CameraParallelScale = this->Camera.orthographic ? this->Camera.parallel_scale : 0.0;
}

//------------------------------------------------------------------------------
vtkFRepRayCaster::vtkFRepRayCaster()
  : Internal(new Internals)
{
  this->SetNumberOfInputPorts(1);
  this->SetNumberOfOutputPorts(1);
}

//------------------------------------------------------------------------------
vtkFRepRayCaster::~vtkFRepRayCaster() = default;

//------------------------------------------------------------------------------
int vtkFRepRayCaster::FillInputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkFRepObject");
  return 1;
}

//------------------------------------------------------------------------------
int vtkFRepRayCaster::RequestInformation(vtkInformation*,
  vtkInformationVector** inputVector,
  vtkInformationVector* outputVector)
{
  Internals& in = *this->Internal;
  in.Valid = false;
  // The object's dimension and intervals from the input's metadata keys: nothing upstream is
  // executed. No keys: an empty object, reported upstream: an empty image, quietly.
  vtkInformation* inInfo = inputVector[0]->GetInformationObject(0);
  vtkFRepInformation::CompleteInputInformation(inInfo); // an input given as data
  vtkFRepInformation::Metadata object;
  if (vtkFRepInformation::Get(inInfo, object))
  {
    std::ostringstream problem;
    const int dimension = object.GetDimension();
    if (dimension != 3)
    {
      problem << object.ObjectName << " has " << dimension
              << " free coordinates; the ray caster draws 3-D objects (fix the others with "
                 "vtkFRepSlice)";
    }
    else
    {
      for (int a = 0; a < 3; ++a)
      {
        double lo = this->ModelBounds[2 * a];
        double hi = this->ModelBounds[2 * a + 1];
        const int coordinate = object.FreeCoordinates[a];
        if (lo > hi) // unset: the object's interval
        {
          lo = object.Ranges[coordinate][0];
          hi = object.Ranges[coordinate][1];
        }
        if (!std::isfinite(lo) || !std::isfinite(hi) || !(lo < hi))
        {
          problem << "axis " << a << " (" << object.Names[coordinate] << "): the box [" << lo
                  << ", " << hi << "] must be finite with min < max";
          break;
        }
        in.Box[2 * a] = lo;
        in.Box[2 * a + 1] = hi;
      }
      if (problem.str().empty() &&
          (!std::isfinite(this->Azimuth) || !std::isfinite(this->Elevation)))
      {
        problem << "Azimuth (" << this->Azimuth << ") and Elevation (" << this->Elevation
                << ") must be finite";
      }
    }
    if (!problem.str().empty())
    {
      vtkErrorMacro(<< problem.str() << "; the output is empty");
    }
    else
    {
      in.Valid = true;
    }
  }

  // The camera needs the solid's bounds, so the tape: it is fitted in RequestData.
  in.Width = in.Valid ? this->Width : 0;
  in.Height = in.Valid ? this->Height : 0;
  if (!in.Valid)
  {
    std::fill(this->CameraPosition, this->CameraPosition + 3, 0.0);
    std::fill(this->CameraFocalPoint, this->CameraFocalPoint + 3, 0.0);
    std::fill(this->CameraViewUp, this->CameraViewUp + 3, 0.0);
    this->CameraParallelScale = 0.0;
  }

  vtkInformation* outInfo = outputVector->GetInformationObject(0);
  vtkFRepInformation::Remove(outInfo); // copied from the input by the executive: not an image's
  const int extent[6] = { 0, in.Width - 1, 0, in.Height - 1, 0, in.Valid ? 0 : -1 };
  const double origin[3] = { 0.0, 0.0, 0.0 };
  const double spacing[3] = { 1.0, 1.0, 1.0 };
  outInfo->Set(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), extent, 6);
  outInfo->Set(vtkDataObject::ORIGIN(), origin, 3);
  outInfo->Set(vtkDataObject::SPACING(), spacing, 3);
  vtkDataObject::SetPointDataActiveScalarInfo(outInfo, VTK_UNSIGNED_CHAR, 4);
  return 1;
}

//------------------------------------------------------------------------------
int vtkFRepRayCaster::RequestUpdateExtent(vtkInformation*,
  vtkInformationVector** inputVector,
  vtkInformationVector*)
{
  vtkFRepInformation::RequestWholeObject(inputVector[0]->GetInformationObject(0));
  return 1;
}

//------------------------------------------------------------------------------
// The engine's picture as the output's point data: Colour (sRGB bytes with alpha) and Depth. The
// engine's rows run top to bottom, VTK's image rows bottom to top. Throws std::bad_alloc.
static void StorePicture(
  const frep::imaging::Image& picture, const std::vector<float>& depth, vtkImageData* output)
{
  const int width = picture.width, height = picture.height;
  const std::size_t pixels = static_cast<std::size_t>(width) * static_cast<std::size_t>(height);
  vtkNew<vtkUnsignedCharArray> rgba;
  rgba->SetName("Colour");
  rgba->SetNumberOfComponents(4);
  vtkNew<vtkFloatArray> distance;
  distance->SetName("Depth");
  distance->SetNumberOfComponents(1);
  if (!rgba->SetNumberOfValues(static_cast<vtkIdType>(4 * pixels)) ||
    !distance->SetNumberOfValues(static_cast<vtkIdType>(pixels)))
  {
    throw std::bad_alloc();
  }
  unsigned char* c = rgba->GetPointer(0);
  float* d = distance->GetPointer(0);
  for (int y = 0; y < height; ++y)
  {
    const std::size_t row = static_cast<std::size_t>(height - 1 - y) * width;
    for (int x = 0; x < width; ++x)
    {
      const float* p = picture.pixel(x, y);
      unsigned char* q = c + 4 * (row + x);
      for (int k = 0; k < 3; ++k)
      {
        q[k] = ToByte(frep::imaging::linear_to_srgb(p[k]));
      }
      q[3] = ToByte(p[3]);
      d[row + x] = depth[static_cast<std::size_t>(y) * width + x];
    }
  }
  output->SetOrigin(0.0, 0.0, 0.0);
  output->SetSpacing(1.0, 1.0, 1.0);
  output->SetExtent(0, width - 1, 0, height - 1, 0, 0);
  output->GetPointData()->SetScalars(rgba);
  output->GetPointData()->AddArray(distance);
}

//------------------------------------------------------------------------------
int vtkFRepRayCaster::RequestData(vtkInformation*,
  vtkInformationVector** inputVector,
  vtkInformationVector* outputVector)
{
  this->Rays = this->Hits = 0;
  vtkImageData* output = vtkImageData::GetData(outputVector->GetInformationObject(0));
  if (!output)
  {
    vtkErrorMacro(<< "the output is not a vtkImageData");
    return 0;
  }
  output->Initialize();
  Internals& in = *this->Internal;
  vtkFRepObject* object = vtkFRepObject::GetData(inputVector[0]);
  if (!in.Valid || !object || !object->HasModel())
  {
    return 1; // refused in RequestInformation (reported there), or an empty input
  }
  const vtkFRepObject::EvaluationDescription description = object->GetEvaluationDescription();
  if (object->GetDimension() != 3 || !description.Tape || description.Tape->input_count != 3)
  {
    vtkErrorMacro(<< "the input changed between the information and the data pass (dimension "
                  << object->GetDimension()
                  << ", not 3); call Modified() on the ray caster; the output is empty");
    return 1;
  }
  this->UpdateProgress(0.0);

  frep::raycast::Shape shape;
  shape.tape = description.Tape;
  for (int a = 0; a < 3; ++a)
  {
    shape.box[a] = { in.Box[2 * a], in.Box[2 * a + 1] };
  }
  const frep::imaging::Rgba colour = frep::imaging::srgb(
    Clamp01(this->Colour[0]), Clamp01(this->Colour[1]), Clamp01(this->Colour[2]));
  shape.colour = { colour.r, colour.g, colour.b };
  frep::raycast::Style style;
  style.render.supersample = this->Supersample;
  style.self_shadows = this->SelfShadows != 0;

  const int width = in.Width, height = in.Height;
  const std::size_t pixels = static_cast<std::size_t>(width) * static_cast<std::size_t>(height);
  try
  {
    frep::imaging::Image picture(width,
      height,
      frep::imaging::srgb(Clamp01(this->Background[0]),
        Clamp01(this->Background[1]),
        Clamp01(this->Background[2]),
        Clamp01(this->Background[3])));
    std::vector<float> depth;

    // Cancellation, polled per tile by the ray caster's participants: CheckAbort() (not
    // thread-safe: it may look upstream and sets AbortOutput) only on the thread executing this
    // filter, which is one of the participants; the others read the atomic AbortExecute and the
    // flag that thread raises. `stopped` remembers that the ray caster was told to stop (its
    // error is then "cancelled", which is not reported).
    const std::thread::id executing = std::this_thread::get_id();
    std::atomic<bool> aborted{ false };
    std::atomic<bool> stopped{ false };
    frep::RunControl run;
    run.threads = this->NumberOfThreads;
    run.cancel = [this, executing, &aborted, &stopped]
    {
      if (std::this_thread::get_id() == executing && this->CheckAbort())
      {
        aborted.store(true, std::memory_order_relaxed);
      }
      const bool stop = aborted.load(std::memory_order_relaxed) ||
                        this->AbortExecute.load(std::memory_order_relaxed) != 0;
      if (stop)
      {
        stopped.store(true, std::memory_order_relaxed);
      }
      return stop;
    };
    // Progress comes on this thread only (raycast::render's promise): UpdateProgress is safe.
    run.progress = [this](double fraction)
    {
      this->UpdateProgress(fraction);
      return true;
    };
    in.Fit(*this, shape); // the camera and the floor, now that the tape is known
    const frep::raycast::Result result = frep::raycast::render(
      picture, in.Camera, shape, in.Floor ? &*in.Floor : nullptr, style, &depth, run);
    this->Rays = result.statistics.rays;
    this->Hits = result.statistics.hits;
    if (!result.ok())
    {
      if (!stopped.load())
      {
        vtkErrorMacro(<< "ray casting " << object->GetObjectName() << ": " << result.error
                      << "; the output is empty");
      }
      return 1; // the output stays empty
    }
    if (picture.width != width || picture.height != height || depth.size() != pixels)
    {
      vtkErrorMacro(<< "the ray caster returned a picture of another size; the output is empty");
      return 1;
    }

    StorePicture(picture, depth, output);
  }
  catch (const std::bad_alloc&)
  {
    vtkErrorMacro(<< "not enough memory for a picture of " << width << " x " << height
                  << " pixels; the output is empty");
    output->Initialize();
    return 1;
  }
  catch (const std::exception& e)
  {
    vtkErrorMacro(<< "ray casting " << object->GetObjectName() << " failed: " << e.what()
                  << "; the output is empty");
    output->Initialize();
    return 1;
  }
  this->UpdateProgress(1.0);
  return 1;
}

//------------------------------------------------------------------------------
void vtkFRepRayCaster::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Width: " << this->Width << "\n";
  os << indent << "Height: " << this->Height << "\n";
  os << indent << "Azimuth: " << this->Azimuth << "\n";
  os << indent << "Elevation: " << this->Elevation << "\n";
  os << indent << "ViewAngle: " << this->ViewAngle << "\n";
  os << indent << "ParallelProjection: " << (this->ParallelProjection ? "On" : "Off") << "\n";
  os << indent << "ModelBounds: (" << this->ModelBounds[0] << ", " << this->ModelBounds[1] << ", "
     << this->ModelBounds[2] << ", " << this->ModelBounds[3] << ", " << this->ModelBounds[4] << ", "
     << this->ModelBounds[5] << ")\n";
  os << indent << "Colour: (" << this->Colour[0] << ", " << this->Colour[1] << ", "
     << this->Colour[2] << ")\n";
  os << indent << "Background: (" << this->Background[0] << ", " << this->Background[1] << ", "
     << this->Background[2] << ", " << this->Background[3] << ")\n";
  os << indent << "Supersample: " << this->Supersample << "\n";
  os << indent << "Floor: " << (this->Floor ? "On" : "Off") << "\n";
  os << indent << "FrameSolid: " << (this->FrameSolid ? "On" : "Off") << "\n";
  os << indent << "SelfShadows: " << (this->SelfShadows ? "On" : "Off") << "\n";
  os << indent << "NumberOfThreads: " << this->NumberOfThreads << "\n";
  os << indent << "CameraPosition: (" << this->CameraPosition[0] << ", " << this->CameraPosition[1]
     << ", " << this->CameraPosition[2] << ")\n";
  os << indent << "CameraFocalPoint: (" << this->CameraFocalPoint[0] << ", "
     << this->CameraFocalPoint[1] << ", " << this->CameraFocalPoint[2] << ")\n";
  os << indent << "CameraViewUp: (" << this->CameraViewUp[0] << ", " << this->CameraViewUp[1]
     << ", " << this->CameraViewUp[2] << ")\n";
  os << indent << "CameraParallelScale: " << this->CameraParallelScale << "\n";
  os << indent << "NumberOfRays: " << this->Rays << "\n";
  os << indent << "NumberOfHits: " << this->Hits << "\n";
}
