// vtkFRepRayCaster: a sphere of radius 5 drawn in perspective and in parallel projection covers
// the exact projected disc (coverage sum and hit count within 1 %); Depth is the analytic
// distance along the view direction at the centre pixel and off the centre, +inf where nothing
// is hit; the camera frames the solid (a unit ball in the box [-10, 10]^3 covers at least half
// the picture's width or height, a few pixels with FrameSolid off; the sphere's outline fills
// 90 % of the height in parallel projection, the focal point is its centre), or with
// FrameSolid off is fit_box's (distance from the box's bounding sphere), and it is fitted in the
// data pass only; the picture's top row is up (VTK's j grows upwards); Colour is sRGB RGBA with
// the background's alpha; the same arrays for 1 and 2 threads (floor and self-shadows on); the
// floor is framed with the sphere and lies at its lowest point (it stands on it); a 5-D object,
// a flat box, an infinite azimuth and a picture too large for the ray caster are refused with
// one error; an empty input is quiet; RequestInformation executes nothing upstream; an abort
// seen by the cancel callback stops the rays; Set/Get, clamps, PrintSelf.
#include "FRepKitSourcesTestHelpers.h"

#include "vtkAlgorithm.h"
#include "vtkCommand.h"
#include "vtkFRepObject.h"
#include "vtkFRepRayCaster.h"
#include "vtkFloatArray.h"
#include "vtkHyperFunSource.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkSmartPointer.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <iostream>
#include <limits>
#include <numbers>
#include <sstream>
#include <vector>

namespace
{
constexpr double Radius = 5.0;

const char* Sphere = R"(my_model(x[3], a[1])
{
  array c[3];
  c = [0, 0, 0];
  my_model = hfSphere(x, c, 5);
}
)";

// A small ball above the centre: only the upper half of the picture shows it.
const char* HighBall = R"(my_model(x[3], a[1])
{
  array c[3];
  c = [0, 0, 3];
  my_model = hfSphere(x, c, 2);
}
)";

const char* UnitBall = "my_model(x[3], a[1]) { my_model = 1 - x[1]^2 - x[2]^2 - x[3]^2; }";

const char* FiveD = R"(my_model(x[5], a[1])
{
  my_model = 25 - x[1]^2 - x[2]^2 - x[3]^2 - x[4]^2 - x[5]^2;
}
)";

vtkSmartPointer<vtkHyperFunSource> MakeSource(const char* text, double half)
{
  auto source = vtkSmartPointer<vtkHyperFunSource>::New();
  source->SetModelText(text);
  for (int i = 0; i < 3; ++i)
  {
    source->SetCoordinateRange(i, -half, half);
  }
  return source;
}

struct Picture
{
  int Width = 0;
  int Height = 0;
  std::vector<unsigned char> Colour; // 4 per pixel, VTK order (j = 0 the bottom row)
  std::vector<float> Depth;
  bool Valid = false;

  const unsigned char* At(int i, int j) const { return &Colour[4 * (j * Width + i)]; }
  float DepthAt(int i, int j) const { return Depth[j * Width + i]; }
  double Coverage() const // sum of alpha, in pixels
  {
    double sum = 0.0;
    for (std::size_t p = 3; p < Colour.size(); p += 4)
    {
      sum += Colour[p] / 255.0;
    }
    return sum;
  }
  long Hits() const
  {
    return std::count_if(Depth.begin(), Depth.end(), [](float d) { return std::isfinite(d); });
  }
};

Picture Read(vtkFRepRayCaster* caster)
{
  Picture p;
  vtkImageData* image = caster->GetOutput();
  int dims[3];
  image->GetDimensions(dims);
  auto* colour = vtkUnsignedCharArray::SafeDownCast(image->GetPointData()->GetArray("Colour"));
  auto* depth = vtkFloatArray::SafeDownCast(image->GetPointData()->GetArray("Depth"));
  if (!colour || !depth || dims[2] != 1 || colour->GetNumberOfComponents() != 4 ||
      image->GetPointData()->GetScalars() != colour)
  {
    return p;
  }
  p.Width = dims[0];
  p.Height = dims[1];
  const std::size_t n = static_cast<std::size_t>(dims[0]) * dims[1];
  p.Colour.assign(colour->GetPointer(0), colour->GetPointer(0) + 4 * n);
  p.Depth.assign(depth->GetPointer(0), depth->GetPointer(0) + n);
  p.Valid = true;
  return p;
}

// The extent of the pixels hit along the picture's width (axis 0) or height (1), as a fraction.
double HitExtent(const Picture& p, int axis)
{
  int lo = axis ? p.Height : p.Width, hi = -1;
  for (int j = 0; j < p.Height; ++j)
  {
    for (int i = 0; i < p.Width; ++i)
    {
      if (std::isfinite(p.DepthAt(i, j)))
      {
        lo = std::min(lo, axis ? j : i);
        hi = std::max(hi, axis ? j : i);
      }
    }
  }
  return hi < lo ? 0.0 : (hi - lo + 1.0) / (axis ? p.Height : p.Width);
}

double Distance(const double* a, const double* b)
{
  return std::sqrt(
    (a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) + (a[2] - b[2]) * (a[2] - b[2]));
}

bool Near(double got, double expected, double relative)
{
  return std::abs(got - expected) <= relative * std::abs(expected);
}

// Aborts the execution at its first progress report (0: before any ray), so only the ray
// caster's cancel callback can stop it.
class AbortAtStart : public vtkCommand
{
public:
  static AbortAtStart* New() { return new AbortAtStart; }
  void Execute(vtkObject* caller, unsigned long, void* data) override
  {
    const double progress = *static_cast<double*>(data);
    this->Values.push_back(progress);
    if (this->Abort && progress == 0.0)
    {
      static_cast<vtkAlgorithm*>(caller)->AbortExecuteOn();
    }
  }
  std::vector<double> Values;
  bool Abort = false;
};
}

int TestFRepRayCaster(int, char*[])
{
  int failures = 0;
  vtkNew<frepkit_test::EventCounter> events;

  // --- defaults, Set/Get, clamps, PrintSelf
  {
    vtkNew<vtkFRepRayCaster> r;
    events->Observe(r);
    FREPKIT_CHECK(failures, r->GetWidth() == 640 && r->GetHeight() == 480);
    FREPKIT_CHECK(failures, r->GetAzimuth() == 35.0 && r->GetElevation() == 25.0);
    FREPKIT_CHECK(failures, r->GetViewAngle() == 30.0 && !r->GetParallelProjection());
    const double* b = r->GetModelBounds();
    FREPKIT_CHECK(
      failures, b[0] == 0 && b[1] == -1 && b[2] == 0 && b[3] == -1 && b[4] == 0 && b[5] == -1);
    const double* c = r->GetColour();
    FREPKIT_CHECK(failures, c[0] == 0.85 && c[1] == 0.62 && c[2] == 0.38);
    const double* bg = r->GetBackground();
    FREPKIT_CHECK(failures, bg[0] == 1 && bg[1] == 1 && bg[2] == 1 && bg[3] == 1);
    FREPKIT_CHECK(failures, r->GetSupersample() == 2 && !r->GetFloor() && !r->GetSelfShadows());
    FREPKIT_CHECK(failures, r->GetNumberOfThreads() == 0);
    FREPKIT_CHECK(failures, r->GetNumberOfRays() == 0 && r->GetNumberOfHits() == 0);
    r->SetWidth(0);
    r->SetHeight(100000);
    FREPKIT_CHECK(failures, r->GetWidth() == 1 && r->GetHeight() == 16384);
    r->SetSupersample(9);
    FREPKIT_CHECK(failures, r->GetSupersample() == 4);
    r->SetSupersample(0);
    FREPKIT_CHECK(failures, r->GetSupersample() == 1);
    r->SetViewAngle(0.0);
    FREPKIT_CHECK(failures, r->GetViewAngle() == 1.0);
    r->SetNumberOfThreads(-2);
    FREPKIT_CHECK(failures, r->GetNumberOfThreads() == 0);
    FREPKIT_CHECK(failures, r->GetFrameSolid());
    r->FloorOn();
    r->SelfShadowsOn();
    r->ParallelProjectionOn();
    r->FrameSolidOff();
    FREPKIT_CHECK(failures, r->GetFloor() && r->GetSelfShadows() && r->GetParallelProjection());
    std::ostringstream printed;
    r->Print(printed);
    for (const char* line : { "Width: 1",
           "Height: 16384",
           "Supersample: 1",
           "Floor: On",
           "FrameSolid: Off",
           "SelfShadows: On",
           "ParallelProjection: On",
           "Colour: (0.85, 0.62, 0.38)",
           "Background: (1, 1, 1, 1)",
           "NumberOfRays: 0" })
    {
      FREPKIT_CHECK(failures, printed.str().find(line) != std::string::npos);
    }
  }

  auto sphere = MakeSource(Sphere, 6.0); // the object's box: [-6, 6]^3
  vtkNew<frepkit_test::ExecutionCounter> sphereRuns;
  sphere->AddObserver(vtkCommand::EndEvent, sphereRuns);
  const double boxRadius = 6.0 * std::sqrt(3.0); // the bounding sphere fit_box frames
  const double degree = std::numbers::pi / 180.0;

  // --- the information pass: the extent, nothing upstream executed, no camera yet (it needs the
  // function); with FrameSolid off, after the data pass, the box's camera (fit_box)
  {
    vtkNew<vtkFRepRayCaster> r;
    events->Observe(r);
    r->SetInputConnection(sphere->GetOutputPort());
    r->SetWidth(321);
    r->SetHeight(241);
    r->UpdateInformation();
    int extent[6];
    r->GetOutputInformation(0)->Get(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), extent);
    FREPKIT_CHECK(failures,
      extent[0] == 0 && extent[1] == 320 && extent[2] == 0 && extent[3] == 240 && extent[4] == 0 &&
        extent[5] == 0);
    FREPKIT_CHECK(failures, sphereRuns->Count == 0);
    const double origin[3] = { 0, 0, 0 };
    FREPKIT_CHECK(failures, Distance(r->GetCameraPosition(), origin) == 0.0);
    r->FrameSolidOff();
    r->SetSupersample(1);
    r->Update();
    // fit_box: perspective distance r sqrt(1 + 1/t^2), t = 0.9 tan(15 deg) (aspect > 1).
    const double t = 0.9 * std::tan(15.0 * degree);
    const double expected = boxRadius * std::sqrt(1.0 + 1.0 / (t * t));
    FREPKIT_CHECK(failures, Distance(r->GetCameraFocalPoint(), origin) < 1e-12);
    FREPKIT_CHECK(failures, Near(Distance(r->GetCameraPosition(), origin), expected, 1e-12));
    // The direction (azimuth 35, elevation 25): out = (sin az cos el, -cos az cos el, sin el).
    const double* eye = r->GetCameraPosition();
    FREPKIT_CHECK(failures, Near(eye[2], expected * std::sin(25.0 * degree), 1e-12));
    FREPKIT_CHECK(
      failures, Near(eye[0], expected * std::sin(35.0 * degree) * std::cos(25.0 * degree), 1e-12));
    FREPKIT_CHECK(failures, r->GetCameraViewUp()[2] > 0.9);
    // Explicit ModelBounds equal to the object's intervals: the same camera.
    r->SetModelBounds(-6, 6, -6, 6, -6, 6);
    r->Update();
    FREPKIT_CHECK(failures, Near(Distance(r->GetCameraPosition(), origin), expected, 1e-12));
    r->SetModelBounds(-12, 12, -12, 12, -12, 12);
    r->Update();
    FREPKIT_CHECK(failures, Near(Distance(r->GetCameraPosition(), origin), 2 * expected, 1e-12));
    FREPKIT_CHECK(failures, events->Errors == 0 && events->Warnings == 0);
  }

  // --- framing: a unit ball in the box [-10, 10]^3 covers at least half the picture's width or
  // height (the pixels hit); with FrameSolid off (the box's camera) it is a few pixels wide
  {
    auto small = MakeSource(UnitBall, 10.0);
    for (const bool parallel : { false, true })
    {
      vtkNew<vtkFRepRayCaster> r;
      events->Observe(r);
      r->SetInputConnection(small->GetOutputPort());
      r->SetWidth(160);
      r->SetHeight(120);
      r->SetParallelProjection(parallel);
      r->Update();
      const double framed[2] = { HitExtent(Read(r), 0), HitExtent(Read(r), 1) };
      const double origin[3] = { 0, 0, 0 };
      const double focus = Distance(r->GetCameraFocalPoint(), origin);
      r->FrameSolidOff();
      r->Update();
      const double boxed[2] = { HitExtent(Read(r), 0), HitExtent(Read(r), 1) };
      std::cout << (parallel ? "parallel" : "perspective") << ": the unit ball covers " << framed[0]
                << " x " << framed[1] << " of the picture (" << boxed[0] << " x " << boxed[1]
                << " with FrameSolid off); focal point " << focus << " from its centre\n";
      FREPKIT_CHECK(failures, framed[0] >= 0.5 || framed[1] >= 0.5);
      FREPKIT_CHECK(failures, boxed[0] < 0.2 && boxed[1] < 0.2 && boxed[0] > 0.0);
      FREPKIT_CHECK(failures, focus < 1e-6);
      FREPKIT_CHECK(failures, events->Errors == 0 && events->Warnings == 0);
    }
  }

  // --- perspective: the disc's area and the analytic depth
  {
    vtkNew<vtkFRepRayCaster> r;
    events->Observe(r);
    r->SetInputConnection(sphere->GetOutputPort());
    r->SetWidth(321); // odd: the centre pixel's ray is the view axis
    r->SetHeight(241);
    r->SetBackground(1, 1, 1, 0); // transparent: alpha is the coverage
    r->Update();
    const Picture p = Read(r);
    FREPKIT_CHECK(failures, p.Valid && p.Width == 321 && p.Height == 241);
    const double D = Distance(r->GetCameraPosition(), r->GetCameraFocalPoint());
    const double focal = 0.5 * 241 / std::tan(15.0 * degree);
    const double rho = focal * Radius / std::sqrt(D * D - Radius * Radius);
    const double area = std::numbers::pi * rho * rho;
    std::cout << "perspective: distance " << D << ", disc radius " << rho << " px, area " << area
              << ", coverage " << p.Coverage() << ", hit pixels " << p.Hits() << ", rays "
              << r->GetNumberOfRays() << ", hits " << r->GetNumberOfHits() << "\n";
    FREPKIT_CHECK(failures, Near(p.Coverage(), area, 0.01));
    FREPKIT_CHECK(failures, p.Hits() >= p.Coverage()); // edge pixels: any sample hit
    // Depth at the centre: the front of the sphere, D - R along the view direction.
    FREPKIT_CHECK(failures, Near(p.DepthAt(160, 120), D - Radius, 1e-5));
    // 30 pixels right of the centre: the ray F + a R (forward component 1) meets the sphere at
    // lambda = (D - sqrt(D^2 - |d|^2 (D^2 - R^2))) / |d|^2: the depth along the view direction,
    // not the length along the ray.
    const double a = 30.0 / focal, d2 = 1.0 + a * a;
    const double lambda = (D - std::sqrt(D * D - d2 * (D * D - Radius * Radius))) / d2;
    std::cout << "perspective depth: centre " << p.DepthAt(160, 120) << " (" << D - Radius
              << "), 30 px right " << p.DepthAt(190, 120) << " (" << lambda << ")\n";
    FREPKIT_CHECK(failures, Near(p.DepthAt(190, 120), lambda, 1e-5));
    FREPKIT_CHECK(failures, std::isinf(p.DepthAt(0, 0)) && p.DepthAt(0, 0) > 0);
    FREPKIT_CHECK(failures, p.At(0, 0)[3] == 0 && p.At(160, 120)[3] == 255);
    FREPKIT_CHECK(failures, r->GetNumberOfHits() > 0 && r->GetNumberOfRays() >= 321 * 241);
    FREPKIT_CHECK(failures, events->Errors == 0 && events->Warnings == 0);
  }

  // --- parallel projection, one ray per pixel: the hit count and the depth
  {
    vtkNew<vtkFRepRayCaster> r;
    events->Observe(r);
    r->SetInputConnection(sphere->GetOutputPort());
    r->SetWidth(321);
    r->SetHeight(241);
    r->ParallelProjectionOn();
    r->SetSupersample(1);
    r->SetColour(1, 0, 0);
    r->Update();
    const Picture p = Read(r);
    // The sphere's outline (its silhouette, to a ray's spacing: 2 x 5.25 / 64 at most) fills 90 %
    // of the height.
    const double scale = r->GetCameraParallelScale();
    FREPKIT_CHECK(failures, scale >= Radius / 0.9 && scale <= (Radius + 0.17) / 0.9);
    const double focal = 0.5 * 241 / scale; // pixels per world unit
    const double area = std::numbers::pi * (Radius * focal) * (Radius * focal);
    const double D = Distance(r->GetCameraPosition(), r->GetCameraFocalPoint());
    std::cout << "parallel: disc radius " << Radius * focal << " px, area " << area
              << ", hit pixels " << p.Hits() << ", coverage " << p.Coverage() << "\n";
    FREPKIT_CHECK(failures, p.Valid && Near(static_cast<double>(p.Hits()), area, 0.01));
    FREPKIT_CHECK(failures, Near(p.DepthAt(160, 120), D - Radius, 1e-5));
    const double a = 40.0 / focal; // world units right of the axis
    FREPKIT_CHECK(
      failures, Near(p.DepthAt(200, 120), D - std::sqrt(Radius * Radius - a * a), 1e-5));
    // Opaque background (the default): alpha 255 everywhere; white where nothing is hit.
    const unsigned char* corner = p.At(0, 0);
    FREPKIT_CHECK(
      failures, corner[0] == 255 && corner[1] == 255 && corner[2] == 255 && corner[3] == 255);
    const unsigned char* centre = p.At(160, 120);
    // red: sRGB (1, 0, 0) shaded, plus a little of the white highlight in every channel
    FREPKIT_CHECK(failures,
      centre[3] == 255 && centre[0] > 100 && centre[0] > 3 * centre[1] && centre[1] == centre[2]);
    FREPKIT_CHECK(failures, events->Errors == 0 && events->Warnings == 0);
  }

  // --- the picture's top is up: a ball above the centre fills rows j > H / 2 (VTK order)
  {
    auto high = MakeSource(HighBall, 6.0);
    vtkNew<vtkFRepRayCaster> r;
    r->FrameSolidOff(); // the box's centre in the middle of the picture, the ball above it
    r->SetInputConnection(high->GetOutputPort());
    r->SetWidth(161);
    r->SetHeight(121);
    r->SetElevation(0.0);
    r->Update();
    const Picture p = Read(r);
    long above = 0, below = 0;
    for (int j = 0; j < p.Height; ++j)
    {
      for (int i = 0; i < p.Width; ++i)
      {
        if (std::isfinite(p.DepthAt(i, j)))
        {
          (j > p.Height / 2 ? above : below) += 1;
        }
      }
    }
    std::cout << "ball above the centre: " << above << " pixels in the upper half, " << below
              << " in the lower\n";
    // The ball's outline: radius about 2 / (6 sqrt 3) of 0.9 of the half height, 10.5 pixels.
    FREPKIT_CHECK(failures, p.Valid && above > 250 && below == 0);
  }

  // --- the same arrays for 1 and 2 threads (floor and self-shadows on); the floor is seen
  {
    vtkNew<vtkFRepRayCaster> r;
    events->Observe(r);
    r->SetInputConnection(sphere->GetOutputPort());
    r->SetWidth(200);
    r->SetHeight(150);
    r->Update();
    const long withoutFloor = Read(r).Hits();
    r->FloorOn();
    r->SelfShadowsOn();
    r->SetNumberOfThreads(1);
    r->Update();
    const Picture one = Read(r);
    r->SetNumberOfThreads(2);
    r->Update();
    const Picture two = Read(r);
    FREPKIT_CHECK(failures, one.Valid && two.Valid && one.Colour.size() == two.Colour.size());
    FREPKIT_CHECK(failures, one.Colour == two.Colour);
    FREPKIT_CHECK(failures,
      one.Depth.size() == two.Depth.size() &&
        std::memcmp(one.Depth.data(), two.Depth.data(), one.Depth.size() * sizeof(float)) == 0);
    // One ray per pixel (an edge pixel's depth is the nearest of its samples'): every pixel hit
    // is on the floor plane or on the sphere, and the floor plane is z = -Radius, the sphere's
    // lowest point (the ball stands on the board; the box's bottom z = -6 would leave a gap). Its world point from the camera: eye +
    // Depth (forward + a right + b up), a and b the pixel centre's offsets in units of the
    // focal length (the engine's rows run top down: row = Height - 1 - j).
    r->SetSupersample(1);
    r->Update();
    const Picture centres = Read(r);
    const double* eye = r->GetCameraPosition();
    const double* focus = r->GetCameraFocalPoint();
    const double* up = r->GetCameraViewUp();
    double f[3] = { focus[0] - eye[0], focus[1] - eye[1], focus[2] - eye[2] };
    const double fl = std::sqrt(f[0] * f[0] + f[1] * f[1] + f[2] * f[2]);
    for (double& v : f)
    {
      v /= fl;
    }
    const double right[3] = {
      f[1] * up[2] - f[2] * up[1], f[2] * up[0] - f[0] * up[2], f[0] * up[1] - f[1] * up[0]
    };
    const double focal = 0.5 * centres.Height / std::tan(15.0 * degree);
    long onFloor = 0, onSphere = 0;
    for (int j = 0; j < centres.Height; ++j)
    {
      for (int i = 0; i < centres.Width; ++i)
      {
        const double lambda = centres.DepthAt(i, j);
        if (!std::isfinite(lambda))
        {
          continue;
        }
        const double a = (i + 0.5 - 0.5 * centres.Width) / focal;
        const double b = (0.5 * centres.Height - (centres.Height - 1 - j + 0.5)) / focal;
        double w[3];
        for (int k = 0; k < 3; ++k)
        {
          w[k] = eye[k] + lambda * (f[k] + a * right[k] + b * up[k]);
        }
        onFloor += std::abs(w[2] + Radius) < 1e-3 ? 1 : 0;
        onSphere += std::abs(std::sqrt(w[0] * w[0] + w[1] * w[1] + w[2] * w[2]) - Radius) < 1e-3;
      }
    }
    std::cout << "floor: " << centres.Hits() << " pixels hit (" << withoutFloor
              << " without the floor): " << onFloor << " on the floor plane, " << onSphere
              << " on the sphere\n";
    FREPKIT_CHECK(failures, onFloor > 2000 && onSphere > 1000);
    FREPKIT_CHECK(failures, onFloor + onSphere == centres.Hits());
    FREPKIT_CHECK(failures, events->Errors == 0 && events->Warnings == 0);
  }

  // --- refused: a 5-D object, a flat box, an infinite azimuth; an empty input is quiet
  {
    vtkNew<vtkFRepRayCaster> r;
    events->Observe(r);
    auto five = MakeSource(FiveD, 6.0);
    r->SetInputConnection(five->GetOutputPort());
    events->Clear();
    r->Update();
    int extent[6];
    r->GetOutputInformation(0)->Get(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), extent);
    FREPKIT_CHECK(failures, events->Errors == 1 && r->GetOutput()->GetNumberOfPoints() == 0);
    FREPKIT_CHECK(failures,
      events->ErrorText.find("5 free coordinates") != std::string::npos &&
        events->ErrorText.find("vtkFRepSlice") != std::string::npos);
    FREPKIT_CHECK(failures, extent[1] < extent[0]);

    r->SetInputConnection(sphere->GetOutputPort());
    r->SetModelBounds(-1, 1, 2, 2, -1, 1);
    events->Clear();
    r->Update();
    FREPKIT_CHECK(failures, events->Errors == 1 && r->GetOutput()->GetNumberOfPoints() == 0);
    FREPKIT_CHECK(failures, events->ErrorText.find("min < max") != std::string::npos);
    r->SetModelBounds(0, -1, 0, -1, 0, -1);
    r->SetAzimuth(std::numeric_limits<double>::infinity());
    events->Clear();
    r->Update();
    FREPKIT_CHECK(failures, events->Errors == 1 && r->GetOutput()->GetNumberOfPoints() == 0);
    r->SetAzimuth(35.0);
    r->SetWidth(9000); // 4 x 9000 samples on a side: more than the ray caster takes
    r->SetHeight(48);
    r->SetSupersample(4);
    events->Clear();
    r->Update();
    FREPKIT_CHECK(failures, events->Errors == 1 && r->GetOutput()->GetNumberOfPoints() == 0);
    FREPKIT_CHECK(failures, events->ErrorText.find("32768") != std::string::npos);
    r->SetWidth(64);
    r->SetSupersample(2);
    events->Clear();
    r->Update();
    FREPKIT_CHECK(failures, events->Errors == 0 && r->GetOutput()->GetNumberOfPoints() == 64 * 48);

    auto broken = MakeSource("my_model(x[3], a[1]) { my_model = 1 +; }", 6.0);
    vtkNew<frepkit_test::EventCounter> brokenEvents;
    brokenEvents->Observe(broken);
    r->SetInputConnection(broken->GetOutputPort());
    events->Clear();
    r->Update();
    FREPKIT_CHECK(failures, brokenEvents->Errors >= 1);
    FREPKIT_CHECK(failures, events->Errors == 0 && events->Warnings == 0);
    FREPKIT_CHECK(failures, r->GetOutput()->GetNumberOfPoints() == 0);
  }

  // --- an object given as data (SetInputData) is described from the object
  {
    sphere->Update();
    vtkNew<vtkFRepObject> copy;
    copy->ShallowCopy(sphere->GetOutput());
    vtkNew<vtkFRepRayCaster> r;
    events->Observe(r);
    r->SetInputData(copy);
    r->SetWidth(80);
    r->SetHeight(60);
    r->Update();
    FREPKIT_CHECK(failures, r->GetOutput()->GetNumberOfPoints() == 80 * 60);
    FREPKIT_CHECK(failures, Read(r).Hits() > 100);
  }

  // --- progress 0 and 1; an abort at the start is seen by the cancel callback: few rays
  {
    vtkNew<vtkFRepRayCaster> r;
    events->Observe(r);
    r->SetInputConnection(sphere->GetOutputPort());
    r->SetWidth(320);
    r->SetHeight(240);
    vtkNew<AbortAtStart> progress;
    r->AddObserver(vtkCommand::ProgressEvent, progress);
    r->Update();
    FREPKIT_CHECK(failures,
      progress->Values.size() > 2 && progress->Values.front() == 0.0 &&
        progress->Values.back() == 1.0);
    // Per tile in between, rising.
    FREPKIT_CHECK(failures,
      std::is_sorted(progress->Values.begin(), progress->Values.end()) &&
        std::any_of(progress->Values.begin(), progress->Values.end(),
          [](double v) { return v > 0.0 && v < 1.0; }));
    FREPKIT_CHECK(failures, r->GetOutput()->GetNumberOfPoints() == 320 * 240);
    progress->Abort = true;
    r->Modified();
    r->Update();
    std::cout << "aborted: " << r->GetNumberOfRays() << " rays cast\n";
    FREPKIT_CHECK(failures, r->GetOutput()->GetNumberOfPoints() == 0);
    FREPKIT_CHECK(failures, r->GetNumberOfRays() < 320 * 240 / 8);
    progress->Abort = false;
    r->AbortExecuteOff();
    r->Modified();
    r->Update();
    FREPKIT_CHECK(failures, r->GetOutput()->GetNumberOfPoints() == 320 * 240);
    FREPKIT_CHECK(failures, r->GetNumberOfRays() >= 320 * 240);
  }

  FREPKIT_CHECK(failures, events->Errors == 0);
  return failures == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
