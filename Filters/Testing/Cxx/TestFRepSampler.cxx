// vtkFRepSampler: every sample of a sphere equals frep::PointEvaluator at the documented
// position bit for bit (double; float = the double rounded), dimensions/origin/spacing as
// documented, bounds from the object's intervals by default; a 2-D object gives a z = 1 image;
// a sub-extent request computes only that extent with the same values; gradients and outward
// normals; s[] attributes; run-time errors are NaN with one warning naming file:line:col, or
// hfp's previous value; refused sizes give one error and an empty image without allocating;
// several threads by default; progress rises to 1 and abort empties the output; Set/Get,
// PrintSelf; the image survives a .vti round trip.
#include "FRepKitSourcesTestHelpers.h"

#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkFRepObject.h"
#include "vtkFRepSampler.h"
#include "vtkFloatArray.h"
#include "vtkHyperFunSource.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkSmartPointer.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkXMLImageDataReader.h"
#include "vtkXMLImageDataWriter.h"

#include "Eval/point_evaluator.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <limits>
#include <regex>
#include <sstream>
#include <thread>
#include <vector>

#include <unistd.h> // getpid: a temporary file name of our own

namespace
{
const char* Sphere = R"(my_model(x[3], a[1])
{
  array c[3];
  c = [0, 0, 0];
  my_model = hfSphere(x, c, 5);
}
)";

const char* Ellipse2D = R"(my_model(x[2], a[1])
{
  my_model = 9 - x[1] * x[1] - 4 * x[2] * x[2];
}
)";

const char* WithAttributes = R"(my_model(x[3], a[1], s[2])
{
  s[1] = x[1] + 2 * x[2];
  s[2] = x[3] * x[3] - x[1];
  my_model = 1 - x[1] * x[1];
}
)";

// sqrt of a negative number for x < 0: a run-time error on half of the box.
const char* HalfFails = R"(my_model(x[3], a[1])
{
  my_model = sqrt(x[1]) - 1 + x[2] * x[3];
}
)";

const char* FourD = R"(my_model(x[4], a[1])
{
  my_model = 1 - x[1] * x[1] - x[4] * x[4];
}
)";

bool SameBits(double a, double b)
{
  return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b);
}

vtkSmartPointer<vtkHyperFunSource> MakeSource(const char* text)
{
  auto source = vtkSmartPointer<vtkHyperFunSource>::New();
  source->SetModelText(text);
  // The sampler's default grid is the object's intervals: hfp's default box here, so that the
  // positions below are known (the solid's bounds: TestFRepSolidBounds).
  source->UseSolidBoundsOff();
  return source;
}

// The documented position of sample (i, j, k) of an image made by the sampler.
void Position(vtkImageData* image, const int ijk[3], double x[3])
{
  for (int a = 0; a < 3; ++a)
  {
    x[a] = vtkFRepSampler::SamplePosition(image->GetOrigin()[a], image->GetSpacing()[a], ijk[a]);
  }
}

// Samples whose F is not bit-equal to the point evaluator's at the documented position (float
// output: not equal to that value rounded to float), or whose documented position is not the
// image's own point (vtkImageData::GetPoint).
vtkIdType ValueMismatches(vtkImageData* image, vtkFRepObject* object, bool asFloat = false)
{
  frep::PointEvaluator evaluator(object->GetTape());
  const int dimension = object->GetDimension();
  vtkDataArray* f = image->GetPointData()->GetArray("F");
  if (!f || image->GetNumberOfPoints() == 0)
  {
    return -1;
  }
  const int* e = image->GetExtent();
  vtkIdType mismatches = 0;
  for (int k = e[4]; k <= e[5]; ++k)
  {
    for (int j = e[2]; j <= e[3]; ++j)
    {
      for (int i = e[0]; i <= e[1]; ++i)
      {
        const int ijk[3] = { i, j, k };
        double x[3];
        Position(image, ijk, x);
        const vtkIdType id = image->ComputePointId(const_cast<int*>(ijk));
        double p[3];
        image->GetPoint(id, p);
        const double expected = evaluator.value(std::span<const double>(x, dimension));
        const double got = f->GetTuple1(id);
        const bool same = asFloat ? got == static_cast<double>(static_cast<float>(expected))
                                  : SameBits(got, expected);
        mismatches += (same && p[0] == x[0] && p[1] == x[1] && p[2] == x[2]) ? 0 : 1;
      }
    }
  }
  return mismatches;
}

bool ExtentIs(vtkImageData* image, std::array<int, 6> expected)
{
  const int* e = image->GetExtent();
  return std::equal(e, e + 6, expected.begin());
}

// Progress values as the sampler reports them; can abort the execution at the first report
// strictly between 0 and 1.
class ProgressRecorder : public vtkCommand
{
public:
  static ProgressRecorder* New() { return new ProgressRecorder; }
  void Execute(vtkObject* caller, unsigned long, void* data) override
  {
    const double progress = *static_cast<double*>(data);
    this->Values.push_back(progress);
    if (this->Abort && progress > 0.0 && progress < 1.0)
    {
      static_cast<vtkAlgorithm*>(caller)->AbortExecuteOn();
    }
  }
  std::vector<double> Values;
  bool Abort = false;
};
}

int TestFRepSampler(int, char*[])
{
  int failures = 0;
  vtkNew<frepkit_test::EventCounter> events;

  // --- defaults, Set/Get
  {
    vtkNew<vtkFRepSampler> s;
    events->Observe(s);
    const double* b = s->GetModelBounds();
    FREPKIT_CHECK(failures, b[0] == 0 && b[1] == -1 && b[2] == 0 && b[3] == -1 && b[4] == 0 &&
        b[5] == -1);
    const int* d = s->GetSampleDimensions();
    FREPKIT_CHECK(failures, d[0] == 64 && d[1] == 64 && d[2] == 64);
    FREPKIT_CHECK(failures, s->GetOutputScalarType() == VTK_DOUBLE);
    FREPKIT_CHECK(failures, !s->GetComputeGradients() && !s->GetComputeNormals());
    FREPKIT_CHECK(failures, !s->GetComputeAttributes() && !s->GetHfpErrors());
    FREPKIT_CHECK(failures, s->GetMaximumNumberOfSamples() == (vtkIdType(1) << 31));
    FREPKIT_CHECK(failures, s->GetNumberOfThreads() == 0 && s->GetNumberOfThreadsUsed() == 0);
    FREPKIT_CHECK(failures, s->GetNumberOfEvaluationErrors() == 0);
    s->SetOutputScalarTypeToFloat();
    FREPKIT_CHECK(failures, s->GetOutputScalarType() == VTK_FLOAT);
    s->SetOutputScalarType(VTK_INT); // refused
    FREPKIT_CHECK(failures, s->GetOutputScalarType() == VTK_FLOAT && events->Errors == 1);
    s->ComputeGradientsOn();
    s->ComputeNormalsOn();
    s->ComputeAttributesOn();
    s->HfpErrorsOn();
    FREPKIT_CHECK(failures, s->GetComputeGradients() && s->GetComputeNormals());
    FREPKIT_CHECK(failures, s->GetComputeAttributes() && s->GetHfpErrors());
    s->SetMaximumNumberOfSamples(0); // clamped to 1
    FREPKIT_CHECK(failures, s->GetMaximumNumberOfSamples() == 1);
    s->SetNumberOfThreads(-3); // clamped to 0
    FREPKIT_CHECK(failures, s->GetNumberOfThreads() == 0);
    std::ostringstream printed;
    s->Print(printed);
    FREPKIT_CHECK(failures, printed.str().find("OutputScalarType: VTK_FLOAT") != std::string::npos);
    FREPKIT_CHECK(failures, printed.str().find("HfpErrors: On") != std::string::npos);
    FREPKIT_CHECK(failures, vtkFRepSampler::SamplePosition(-6.0, 0.6, 3) == -6.0 + 3.0 * 0.6);
    events->Clear();
  }

  auto sphere = MakeSource(Sphere);
  sphere->Update();
  vtkFRepObject* sphereObject = sphere->GetOutput();

  // --- a 3-D grid: geometry and every value, bit for bit
  vtkNew<vtkFRepSampler> sampler;
  events->Observe(sampler);
  sampler->SetInputConnection(sphere->GetOutputPort());
  sampler->SetModelBounds(-6, 6, -7, 5, -3, 6);
  sampler->SetSampleDimensions(21, 17, 13);
  sampler->Update();
  vtkImageData* image = sampler->GetOutput();
  int dims[3];
  image->GetDimensions(dims);
  FREPKIT_CHECK(failures, dims[0] == 21 && dims[1] == 17 && dims[2] == 13);
  FREPKIT_CHECK(failures, ExtentIs(image, { 0, 20, 0, 16, 0, 12 }));
  const double* origin = image->GetOrigin();
  const double* spacing = image->GetSpacing();
  FREPKIT_CHECK(failures, origin[0] == -6 && origin[1] == -7 && origin[2] == -3);
  FREPKIT_CHECK(failures, spacing[0] == 12.0 / 20 && spacing[1] == 12.0 / 16);
  FREPKIT_CHECK(failures, spacing[2] == 9.0 / 12);
  vtkDataArray* F = image->GetPointData()->GetScalars();
  FREPKIT_CHECK(failures, F && std::string(F->GetName()) == "F");
  FREPKIT_CHECK(failures, vtkDoubleArray::SafeDownCast(F) != nullptr);
  FREPKIT_CHECK(failures, F && F->GetNumberOfTuples() == 21 * 17 * 13);
  FREPKIT_CHECK(failures, ValueMismatches(image, sphereObject) == 0);
  // FRep's sign: positive inside
  {
    const int centre[3] = { 10, 9, 4 }; // (0, -0.25, 0)
    FREPKIT_CHECK(failures, F->GetTuple1(image->ComputePointId(const_cast<int*>(centre))) > 0);
    FREPKIT_CHECK(failures, F->GetTuple1(0) < 0);
  }
  FREPKIT_CHECK(failures, image->GetPointData()->GetArray("Gradient") == nullptr);
  FREPKIT_CHECK(failures, image->GetPointData()->GetNormals() == nullptr);
  FREPKIT_CHECK(failures, image->GetPointData()->GetArray("s") == nullptr);
  FREPKIT_CHECK(failures, events->Errors == 0 && events->Warnings == 0);

  // --- all cores by default (the engine's pool), and one thread gives the same values
  const unsigned cores = std::thread::hardware_concurrency();
  std::cout << "sampler threads: " << sampler->GetNumberOfThreadsUsed() << " (" << cores
            << " cores)" << std::endl;
  FREPKIT_CHECK(failures, sampler->GetNumberOfThreadsUsed() == static_cast<int>(std::max(1u, cores)));
  if (cores >= 2)
  {
    FREPKIT_CHECK(failures, sampler->GetNumberOfThreadsUsed() >= 2);
  }
  vtkNew<vtkImageData> parallelCopy;
  parallelCopy->DeepCopy(image);
  sampler->SetNumberOfThreads(1);
  sampler->Update();
  FREPKIT_CHECK(failures, sampler->GetNumberOfThreadsUsed() == 1);
  FREPKIT_CHECK(failures, ValueMismatches(sampler->GetOutput(), sphereObject) == 0);
  sampler->SetNumberOfThreads(0);

  // --- an object given directly (no pipeline connection upstream)
  {
    vtkNew<vtkFRepSampler> direct;
    direct->SetInputData(sphereObject);
    direct->SetSampleDimensions(5, 6, 7);
    direct->Update();
    FREPKIT_CHECK(failures, direct->GetOutput()->GetNumberOfPoints() == 5 * 6 * 7);
    FREPKIT_CHECK(failures, ValueMismatches(direct->GetOutput(), sphereObject) == 0);
  }

  // --- the default bounds are the object's intervals; one sample on an axis sits at lo
  {
    auto ranged = MakeSource(Sphere);
    ranged->SetCoordinateRange(0, -1, 3);
    ranged->SetCoordinateRange(1, 2, 2); // zero width: fine with one sample only
    vtkNew<vtkFRepSampler> s;
    events->Observe(s);
    s->SetInputConnection(ranged->GetOutputPort());
    s->SetSampleDimensions(5, 1, 11);
    s->Update();
    vtkImageData* out = s->GetOutput();
    FREPKIT_CHECK(failures, ExtentIs(out, { 0, 4, 0, 0, 0, 10 }));
    FREPKIT_CHECK(failures, out->GetOrigin()[0] == -1 && out->GetSpacing()[0] == 1.0);
    FREPKIT_CHECK(failures, out->GetOrigin()[1] == 2 && out->GetSpacing()[1] == 1.0);
    FREPKIT_CHECK(failures, out->GetOrigin()[2] == -10 && out->GetSpacing()[2] == 2.0);
    ranged->Update();
    FREPKIT_CHECK(failures, ValueMismatches(out, ranged->GetOutput()) == 0);
    // and a zero-width axis with several samples is refused
    s->SetSampleDimensions(5, 2, 11);
    events->Clear();
    s->Update();
    FREPKIT_CHECK(failures, events->Errors == 1 && s->GetOutput()->GetNumberOfPoints() == 0);
    FREPKIT_CHECK(failures, events->ErrorText.find("zero width") != std::string::npos);
    events->Clear();
  }

  // --- float output: the double values rounded
  {
    vtkNew<vtkFRepSampler> s;
    s->SetInputConnection(sphere->GetOutputPort());
    s->SetModelBounds(-6, 6, -7, 5, -3, 6);
    s->SetSampleDimensions(21, 17, 13);
    s->SetOutputScalarTypeToFloat();
    s->ComputeNormalsOn();
    s->Update();
    FREPKIT_CHECK(failures, vtkFloatArray::SafeDownCast(s->GetOutput()->GetPointData()->GetScalars()));
    FREPKIT_CHECK(failures, vtkFloatArray::SafeDownCast(s->GetOutput()->GetPointData()->GetNormals()));
    FREPKIT_CHECK(failures, ValueMismatches(s->GetOutput(), sphereObject, true) == 0);
  }

  // --- a sub-extent: only that extent is computed, with the whole image's values
  {
    vtkNew<vtkFRepSampler> s;
    s->SetInputConnection(sphere->GetOutputPort());
    s->SetModelBounds(-6, 6, -7, 5, -3, 6);
    s->SetSampleDimensions(21, 17, 13);
    const int sub[6] = { 3, 10, 2, 9, 4, 8 };
    s->UpdateExtent(sub);
    vtkImageData* part = s->GetOutput();
    FREPKIT_CHECK(failures, ExtentIs(part, { 3, 10, 2, 9, 4, 8 }));
    FREPKIT_CHECK(failures, part->GetNumberOfPoints() == 8 * 8 * 5);
    FREPKIT_CHECK(failures, part->GetPointData()->GetScalars()->GetNumberOfTuples() == 8 * 8 * 5);
    FREPKIT_CHECK(failures, ValueMismatches(part, sphereObject) == 0);
    vtkIdType differ = 0;
    for (int k = sub[4]; k <= sub[5]; ++k)
    {
      for (int j = sub[2]; j <= sub[3]; ++j)
      {
        for (int i = sub[0]; i <= sub[1]; ++i)
        {
          differ += SameBits(part->GetScalarComponentAsDouble(i, j, k, 0),
                      parallelCopy->GetScalarComponentAsDouble(i, j, k, 0))
            ? 0
            : 1;
        }
      }
    }
    FREPKIT_CHECK(failures, differ == 0);
    // a single row at the far corner
    const int row[6] = { 0, 20, 16, 16, 12, 12 };
    s->UpdateExtent(row);
    FREPKIT_CHECK(failures, ExtentIs(s->GetOutput(), { 0, 20, 16, 16, 12, 12 }));
    FREPKIT_CHECK(failures, s->GetOutput()->GetNumberOfPoints() == 21);
    FREPKIT_CHECK(failures, ValueMismatches(s->GetOutput(), sphereObject) == 0);
  }

  // --- a 2-D object: a z = 1 image whatever SampleDimensions[2] says
  {
    auto ellipse = MakeSource(Ellipse2D);
    vtkNew<vtkFRepSampler> s;
    events->Observe(s);
    s->SetInputConnection(ellipse->GetOutputPort());
    s->SetModelBounds(-4, 4, -2, 2, 5, 9);
    s->SetSampleDimensions(30, 20, 64);
    s->ComputeGradientsOn();
    s->ComputeNormalsOn();
    s->Update();
    vtkImageData* flat = s->GetOutput();
    FREPKIT_CHECK(failures, ExtentIs(flat, { 0, 29, 0, 19, 0, 0 }));
    FREPKIT_CHECK(failures, flat->GetOrigin()[2] == 0 && flat->GetSpacing()[2] == 1);
    ellipse->Update();
    FREPKIT_CHECK(failures, ValueMismatches(flat, ellipse->GetOutput()) == 0);
    vtkDataArray* g = flat->GetPointData()->GetArray("Gradient");
    vtkDataArray* n = flat->GetPointData()->GetNormals();
    vtkIdType wrong = 0;
    for (vtkIdType id = 0; g && n && id < flat->GetNumberOfPoints(); ++id)
    {
      double p[3], gv[3], nv[3];
      flat->GetPoint(id, p);
      g->GetTuple(id, gv);
      n->GetTuple(id, nv);
      // F = 9 - x^2 - 4 y^2: grad = (-2x, -8y, 0)
      wrong += std::abs(gv[0] + 2 * p[0]) > 1e-12 || std::abs(gv[1] + 8 * p[1]) > 1e-12 ||
          gv[2] != 0 || nv[2] != 0
        ? 1
        : 0;
    }
    FREPKIT_CHECK(failures, g && n && wrong == 0);
    FREPKIT_CHECK(failures, events->Errors == 0 && events->Warnings == 0);
  }

  // --- gradients and outward unit normals of the sphere
  {
    vtkNew<vtkFRepSampler> s;
    s->SetInputConnection(sphere->GetOutputPort());
    s->SetModelBounds(-6, 6, -6, 6, -6, 6);
    s->SetSampleDimensions(24, 24, 24); // no sample at the centre
    s->ComputeGradientsOn();
    s->ComputeNormalsOn();
    s->Update();
    vtkImageData* out = s->GetOutput();
    vtkDataArray* g = out->GetPointData()->GetArray("Gradient");
    vtkDataArray* n = out->GetPointData()->GetNormals();
    FREPKIT_CHECK(failures, g && g->GetNumberOfComponents() == 3);
    FREPKIT_CHECK(failures, n && n->GetNumberOfComponents() == 3 &&
        std::string(n->GetName()) == "Normals");
    vtkIdType inward = 0, badGradient = 0, notUnit = 0;
    for (vtkIdType id = 0; g && n && id < out->GetNumberOfPoints(); ++id)
    {
      double p[3], gv[3], nv[3];
      out->GetPoint(id, p);
      g->GetTuple(id, gv);
      n->GetTuple(id, nv);
      const double r = std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
      const double dot = (nv[0] * p[0] + nv[1] * p[1] + nv[2] * p[2]) / r;
      inward += dot > 0.99 ? 0 : 1;
      notUnit += std::abs(vtkMath::Norm(nv) - 1.0) < 1e-12 ? 0 : 1;
      for (int k = 0; k < 3; ++k)
      {
        badGradient += std::abs(gv[k] + 2 * p[k]) <= 1e-12 * (1 + std::abs(p[k])) ? 0 : 1;
      }
    }
    FREPKIT_CHECK(failures, inward == 0 && notUnit == 0 && badGradient == 0);
    FREPKIT_CHECK(failures, ValueMismatches(out, sphereObject) == 0); // F unchanged
  }

  // --- s[] attributes: one array with s_dim components, the point evaluator's values
  {
    auto attributed = MakeSource(WithAttributes);
    vtkNew<vtkFRepSampler> s;
    s->SetInputConnection(attributed->GetOutputPort());
    s->SetSampleDimensions(9, 8, 7);
    s->ComputeAttributesOn();
    s->Update();
    vtkImageData* out = s->GetOutput();
    vtkDataArray* a = out->GetPointData()->GetArray("s");
    FREPKIT_CHECK(failures, a && a->GetNumberOfComponents() == 2);
    attributed->Update();
    frep::PointEvaluator evaluator(attributed->GetOutput()->GetTape());
    std::vector<double> outputs(3);
    vtkIdType wrong = 0;
    for (vtkIdType id = 0; a && id < out->GetNumberOfPoints(); ++id)
    {
      double p[3];
      out->GetPoint(id, p);
      evaluator.evaluate(std::span<const double>(p, 3), outputs);
      wrong += SameBits(a->GetComponent(id, 0), outputs[1]) &&
          SameBits(a->GetComponent(id, 1), outputs[2]) &&
          SameBits(out->GetPointData()->GetScalars()->GetTuple1(id), outputs[0])
        ? 0
        : 1;
      wrong += a->GetComponent(id, 0) == p[0] + 2 * p[1] ? 0 : 1; // and they mean what we think
    }
    FREPKIT_CHECK(failures, wrong == 0);
    // a model without s[] has s_dim 1: s[1] = 0
    vtkNew<vtkFRepSampler> plain;
    plain->SetInputConnection(sphere->GetOutputPort());
    plain->SetSampleDimensions(4, 4, 4);
    plain->ComputeAttributesOn();
    plain->Update();
    vtkDataArray* zero = plain->GetOutput()->GetPointData()->GetArray("s");
    FREPKIT_CHECK(failures, zero && zero->GetNumberOfComponents() == 1 && zero->GetRange()[0] == 0 &&
        zero->GetRange()[1] == 0);
  }

  // --- run-time errors: NaN and one warning with file:line:col, or hfp's previous value
  {
    auto failing = MakeSource(HalfFails);
    failing->SetCoordinateRange(0, -2, 2.5); // no sample at x = 0 (sqrt' infinite)
    vtkNew<vtkFRepSampler> s;
    events->Observe(s);
    s->SetInputConnection(failing->GetOutputPort());
    s->SetSampleDimensions(9, 300, 30); // x = -2 + i * 0.5625: 4 of 9 fail; several slabs
    s->ComputeGradientsOn();
    s->ComputeNormalsOn();
    s->ComputeAttributesOn();
    events->Clear();
    s->Update();
    vtkImageData* out = s->GetOutput();
    vtkDataArray* f = out->GetPointData()->GetScalars();
    vtkIdType nan = 0, wrong = 0;
    for (vtkIdType id = 0; id < out->GetNumberOfPoints(); ++id)
    {
      double p[3];
      out->GetPoint(id, p);
      const bool isNaN = std::isnan(f->GetTuple1(id));
      nan += isNaN ? 1 : 0;
      wrong += isNaN == (p[0] < 0) ? 0 : 1;
      for (const char* name : { "Gradient", "Normals", "s" })
      {
        vtkDataArray* a = out->GetPointData()->GetArray(name);
        wrong += (a && std::isnan(a->GetComponent(id, 0)) == isNaN) ? 0 : 1;
      }
    }
    const vtkIdType expected = 4 * 300 * 30;
    FREPKIT_CHECK(failures, nan == expected && wrong == 0);
    FREPKIT_CHECK(failures, s->GetNumberOfEvaluationErrors() == expected);
    FREPKIT_CHECK(failures, events->Warnings == 1 && events->Errors == 0);
    std::cout << "warning: " << events->WarningText << std::endl;
    FREPKIT_CHECK(failures, events->WarningText.find(std::to_string(expected)) != std::string::npos);
    FREPKIT_CHECK(failures, std::regex_search(events->WarningText, std::regex("<string>:3:\\d+: error: ")));
    FREPKIT_CHECK(failures, events->WarningText.find("at (-2, -10, -10)") != std::string::npos);

    // hfp: finite everywhere; a failed sample repeats the previous one, 0 at the first
    s->HfpErrorsOn();
    events->Clear();
    s->Update();
    out = s->GetOutput();
    f = out->GetPointData()->GetScalars();
    vtkIdType notFinite = 0, notPrevious = 0;
    for (vtkIdType id = 0; id < out->GetNumberOfPoints(); ++id)
    {
      double p[3];
      out->GetPoint(id, p);
      for (const char* name : { "F", "Gradient", "Normals", "s" })
      {
        vtkDataArray* a = out->GetPointData()->GetArray(name);
        for (int c = 0; c < a->GetNumberOfComponents(); ++c)
        {
          const double v = a->GetComponent(id, c);
          notFinite += std::isfinite(v) ? 0 : 1; // (sqrt is differentiable where it succeeds)
          if (p[0] < 0)
          {
            notPrevious += v == (id == 0 ? 0.0 : a->GetComponent(id - 1, c)) ? 0 : 1;
          }
        }
      }
    }
    FREPKIT_CHECK(failures, notFinite == 0 && notPrevious == 0);
    FREPKIT_CHECK(failures, f->GetTuple1(0) == 0.0);
    FREPKIT_CHECK(failures, s->GetNumberOfEvaluationErrors() == expected);
    FREPKIT_CHECK(failures, events->Warnings == 1 && events->WarningText.find("HfpErrors") !=
        std::string::npos);
    events->Clear();
  }

  // --- refused requests: one error, an empty image, nothing allocated
  {
    vtkNew<vtkFRepSampler> s;
    events->Observe(s);
    s->SetInputConnection(sphere->GetOutputPort());
    s->SetSampleDimensions(100000, 100000, 100000); // 10^15 samples: 8 PB in double
    events->Clear();
    s->Update();
    FREPKIT_CHECK(failures, events->Errors == 1 && s->GetOutput()->GetNumberOfPoints() == 0);
    FREPKIT_CHECK(failures, events->ErrorText.find("MaximumNumberOfSamples") != std::string::npos);
    FREPKIT_CHECK(failures, s->GetOutput()->GetPointData()->GetNumberOfArrays() == 0);
    int whole[6];
    s->GetOutputInformation(0)->Get(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), whole);
    FREPKIT_CHECK(failures, whole[0] > whole[1]);
    // the limit is a property
    s->SetSampleDimensions(11, 11, 11);
    s->SetMaximumNumberOfSamples(1000);
    events->Clear();
    s->Update();
    FREPKIT_CHECK(failures, events->Errors == 1 && s->GetOutput()->GetNumberOfPoints() == 0);
    s->SetMaximumNumberOfSamples(1331);
    events->Clear();
    s->Update();
    FREPKIT_CHECK(failures, events->Errors == 0 && s->GetOutput()->GetNumberOfPoints() == 1331);
    // dimensions below 1, non-finite bounds
    s->SetSampleDimensions(11, 0, 11);
    events->Clear();
    s->Update();
    FREPKIT_CHECK(failures, events->Errors == 1 && s->GetOutput()->GetNumberOfPoints() == 0);
    FREPKIT_CHECK(failures, events->ErrorText.find("at least 1") != std::string::npos);
    s->SetSampleDimensions(11, 11, 11);
    s->SetModelBounds(-1, std::numeric_limits<double>::infinity(), -1, 1, -1, 1);
    events->Clear();
    s->Update();
    FREPKIT_CHECK(failures, events->Errors == 1 && s->GetOutput()->GetNumberOfPoints() == 0);
    // a 4-D object
    auto four = MakeSource(FourD);
    s->SetInputConnection(four->GetOutputPort());
    s->SetModelBounds(-1, 1, -1, 1, -1, 1);
    events->Clear();
    s->Update();
    FREPKIT_CHECK(failures, events->Errors == 1 && s->GetOutput()->GetNumberOfPoints() == 0);
    FREPKIT_CHECK(failures, events->ErrorText.find("vtkFRepSlice") != std::string::npos);
    // an empty input (a parse error upstream): quiet
    auto broken = MakeSource("my_model(x[3], a[1]) { my_model = 1 +; }");
    vtkNew<frepkit_test::EventCounter> brokenEvents;
    brokenEvents->Observe(broken);
    s->SetInputConnection(broken->GetOutputPort());
    events->Clear();
    s->Update();
    FREPKIT_CHECK(failures, brokenEvents->Errors >= 1);
    FREPKIT_CHECK(failures, events->Errors == 0 && events->Warnings == 0);
    FREPKIT_CHECK(failures, s->GetOutput()->GetNumberOfPoints() == 0);
  }

  // --- progress per slab, rising to 1; an abort leaves an empty image
  {
    vtkNew<vtkFRepSampler> s;
    s->SetInputConnection(sphere->GetOutputPort());
    s->SetSampleDimensions(64, 64, 64); // 4 slabs
    vtkNew<ProgressRecorder> progress;
    s->AddObserver(vtkCommand::ProgressEvent, progress);
    s->Update();
    const std::vector<double>& v = progress->Values;
    FREPKIT_CHECK(failures, v.size() >= 5 && v.back() == 1.0);
    FREPKIT_CHECK(failures, std::is_sorted(v.begin(), v.end()));
    FREPKIT_CHECK(failures, std::count(v.begin(), v.end(), 0.5) == 1); // one report per slab
    FREPKIT_CHECK(failures, s->GetOutput()->GetNumberOfPoints() == 64 * 64 * 64);

    progress->Values.clear();
    progress->Abort = true;
    s->Modified();
    s->Update();
    // aborted after the first slab (0.25): the later slabs (0.5, 0.75) never ran; VTK itself
    // reports 1 at the end of an execution, aborted or not
    FREPKIT_CHECK(failures, s->GetOutput()->GetNumberOfPoints() == 0);
    FREPKIT_CHECK(failures, std::count(v.begin(), v.end(), 0.25) == 1);
    FREPKIT_CHECK(failures, std::count(v.begin(), v.end(), 0.5) == 0);
    FREPKIT_CHECK(failures, std::count(v.begin(), v.end(), 0.75) == 0);
    progress->Abort = false;
    s->AbortExecuteOff();
    s->Modified();
    s->Update();
    FREPKIT_CHECK(failures, s->GetOutput()->GetNumberOfPoints() == 64 * 64 * 64);
  }

  // --- the image is an ordinary vtkImageData: a .vti round trip keeps F
  {
    const std::filesystem::path file = std::filesystem::temp_directory_path() /
      ("TestFRepSampler-" + std::to_string(::getpid()) + ".vti");
    vtkNew<vtkXMLImageDataWriter> writer;
    writer->SetInputData(parallelCopy);
    // Inline base64, not appended data: Debian 12's expat (with the reparse-deferral security
    // fix) breaks VTK 9.2's reader of appended data ("junk after document element", VTK
    // issue 19258).
    writer->SetDataModeToBinary();
    writer->SetFileName(file.string().c_str());
    FREPKIT_CHECK(failures, writer->Write() == 1);
    vtkNew<vtkXMLImageDataReader> reader;
    reader->SetFileName(file.string().c_str());
    reader->Update();
    FREPKIT_CHECK(failures, ValueMismatches(reader->GetOutput(), sphereObject) == 0);
    std::filesystem::remove(file);
  }

  FREPKIT_CHECK(failures, events->Errors == 0);
  return failures == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
