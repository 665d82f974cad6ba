// vtkHyperFunSource (n-D) -> vtkFRepSlice -> vtkFRepSampler as one pipeline: the image equals
// the n-D tape evaluated at the slice values; changing the slice value, the source's a[] or
// the file re-executes it with new values; the information pass runs nobody; the source runs
// once per update; two pieces of the image (as two MPI ranks would ask) together are the whole
// image; the 5-D homotopy of
// Examples/ sliced by name at (x4, x5) = (0.25, 0.75).
#include "FRepKitSourcesTestHelpers.h"

#include "vtkDataArray.h"
#include "vtkFRepObject.h"
#include "vtkFRepSampler.h"
#include "vtkFRepSlice.h"
#include "vtkFlyingEdges3D.h"
#include "vtkHyperFunSource.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"

#include "Eval/point_evaluator.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <set>
#include <string>
#include <vector>

namespace
{
// A ball whose radius grows with x4 and a[1].
const char* Model4D = R"(my_model(x[4], a[1])
{
  r = 2 + a[1] + x[4];
  my_model = r * r - x[1] * x[1] - x[2] * x[2] - x[3] * x[3];
}
)";

bool SameBits(double a, double b)
{
  return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b);
}

// Samples of `image` that differ (bit for bit) from the n-D object `full` evaluated at the
// sample's position in the free coordinates `axes` and at `fixed` values elsewhere.
vtkIdType Mismatches(vtkImageData* image,
  vtkFRepObject* full,
  const std::vector<int>& axes,
  const std::vector<std::pair<int, double>>& fixed)
{
  frep::PointEvaluator evaluator(full->GetTape());
  vtkDataArray* f = image->GetPointData()->GetScalars();
  if (!f || image->GetNumberOfPoints() == 0)
  {
    return -1;
  }
  std::vector<double> x(full->GetDimension());
  vtkIdType mismatches = 0;
  for (vtkIdType id = 0; id < image->GetNumberOfPoints(); ++id)
  {
    double p[3];
    image->GetPoint(id, p);
    for (std::size_t a = 0; a < axes.size(); ++a)
    {
      x[axes[a]] = p[a];
    }
    for (const auto& [c, v] : fixed)
    {
      x[c] = v;
    }
    mismatches += SameBits(f->GetTuple1(id), evaluator.value(x)) ? 0 : 1;
  }
  return mismatches;
}

}

int TestFRepSlicePipeline(int, char*[])
{
  int failures = 0;
  vtkNew<vtkHyperFunSource> source;
  source->SetModelText(Model4D);
  vtkNew<vtkFRepSlice> slice;
  slice->SetInputConnection(source->GetOutputPort());
  slice->SetFixedValue(3, 0.5);
  vtkNew<vtkFRepSampler> sampler;
  sampler->SetInputConnection(slice->GetOutputPort());
  sampler->SetModelBounds(-4, 4, -4, 4, -4, 4);
  sampler->SetSampleDimensions(16, 15, 14);

  vtkNew<frepkit_test::EventCounter> events;
  events->Observe(source);
  events->Observe(slice);
  events->Observe(sampler);
  vtkNew<frepkit_test::ExecutionCounter> sourceRuns;
  source->AddObserver(vtkCommand::EndEvent, sourceRuns);
  vtkNew<frepkit_test::ExecutionCounter> samplerRuns;
  sampler->AddObserver(vtkCommand::EndEvent, samplerRuns);

  // An unsliced full object to compare with (its own source: the pipeline's is not touched).
  vtkNew<vtkHyperFunSource> reference;
  reference->SetModelText(Model4D);
  reference->Update();
  vtkFRepObject* full = reference->GetOutput();

  // --- the information pass runs nobody (the grid comes from information keys)
  sampler->UpdateInformation();
  FREPKIT_CHECK(failures, sourceRuns->Count == 0 && samplerRuns->Count == 0);

  // --- one update runs everything once, with the slice's values
  sampler->Update();
  vtkImageData* image = sampler->GetOutput();
  FREPKIT_CHECK(failures, image->GetNumberOfPoints() == 16 * 15 * 14);
  FREPKIT_CHECK(failures, Mismatches(image, full, { 0, 1, 2 }, { { 3, 0.5 } }) == 0);
  FREPKIT_CHECK(failures, sourceRuns->Count == 1 && samplerRuns->Count == 1);
  const double centre05 = image->GetPointData()->GetScalars()->GetTuple1(0);

  // the image contours as VTK expects (F = 0): the sphere of radius 2 + 0 + 0.5
  {
    vtkNew<vtkFRepSampler> fine;
    fine->SetInputConnection(slice->GetOutputPort());
    fine->SetModelBounds(-3, 3, -3, 3, -3, 3);
    fine->SetSampleDimensions(61, 61, 61);
    vtkNew<vtkFlyingEdges3D> contour;
    contour->SetInputConnection(fine->GetOutputPort());
    contour->SetValue(0, 0.0);
    contour->Update();
    vtkPolyData* surface = contour->GetOutput();
    double worst = 0;
    for (vtkIdType i = 0; i < surface->GetNumberOfPoints(); ++i)
    {
      double p[3];
      surface->GetPoint(i, p);
      worst = std::max(worst, std::abs(std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]) - 2.5));
    }
    std::cout << "contour: " << surface->GetNumberOfPoints() << " points, radius error " << worst
              << std::endl;
    FREPKIT_CHECK(failures, surface->GetNumberOfPoints() > 1000 && worst < 0.01);
    FREPKIT_CHECK(failures, sourceRuns->Count == 1); // the slice's output was up to date
  }

  // nothing changed: nothing runs again
  sampler->Update();
  FREPKIT_CHECK(failures, sourceRuns->Count == 1 && samplerRuns->Count == 1);

  // --- a new slice value re-executes slice and sampler (not the source) with new values
  slice->SetFixedValue(3, 1.0);
  sampler->Update();
  FREPKIT_CHECK(failures, samplerRuns->Count == 2 && sourceRuns->Count == 1);
  FREPKIT_CHECK(failures, image->GetPointData()->GetScalars()->GetTuple1(0) != centre05);
  FREPKIT_CHECK(failures, Mismatches(image, full, { 0, 1, 2 }, { { 3, 1.0 } }) == 0);
  FREPKIT_CHECK(failures, Mismatches(image, full, { 0, 1, 2 }, { { 3, 0.5 } }) > 0);

  // --- a new a[1] at the source re-executes all of it
  source->SetParameter(0, 1.5);
  reference->SetParameter(0, 1.5);
  reference->Update();
  sampler->Update();
  FREPKIT_CHECK(failures, samplerRuns->Count == 3 && sourceRuns->Count == 2);
  FREPKIT_CHECK(failures, Mismatches(image, reference->GetOutput(), { 0, 1, 2 }, { { 3, 1.0 } }) == 0);

  // --- the free coordinate order reaches the image: axis x is model coordinate x3
  slice->SetFreeCoordinateOrder("x3,x1,x2");
  sampler->Update();
  FREPKIT_CHECK(failures, Mismatches(image, reference->GetOutput(), { 2, 0, 1 }, { { 3, 1.0 } }) == 0);
  slice->SetFreeCoordinateOrder(nullptr);

  // --- a bad slice: one error (from the slice), an empty image, no cascade
  slice->SetFixedValueByName("w", 0.0);
  events->Clear();
  sampler->Update();
  FREPKIT_CHECK(failures, events->Errors == 1 && events->Warnings == 0);
  FREPKIT_CHECK(failures, sampler->GetOutput()->GetNumberOfPoints() == 0);
  slice->ReleaseCoordinateByName("w");
  events->Clear();
  sampler->Update();
  FREPKIT_CHECK(failures, events->Errors == 0 && image->GetNumberOfPoints() == 16 * 15 * 14);

  // --- two pieces, as two MPI ranks would request them, make the whole image
  {
    std::set<vtkIdType> covered;
    vtkIdType wrong = 0;
    int pieceCount = 0;
    for (int piece = 0; piece < 2; ++piece)
    {
      sampler->UpdatePiece(piece, 2, 0);
      vtkImageData* part = sampler->GetOutput();
      const int* e = part->GetExtent();
      std::cout << "piece " << piece << ": extent " << e[0] << ".." << e[1] << " " << e[2]
                << ".." << e[3] << " " << e[4] << ".." << e[5] << std::endl;
      pieceCount += part->GetNumberOfPoints() < 16 * 15 * 14 ? 1 : 0;
      wrong += Mismatches(part, reference->GetOutput(), { 0, 1, 2 }, { { 3, 1.0 } });
      for (int k = e[4]; k <= e[5]; ++k)
      {
        for (int j = e[2]; j <= e[3]; ++j)
        {
          for (int i = e[0]; i <= e[1]; ++i)
          {
            covered.insert(i + 16 * (j + 15 * k));
          }
        }
      }
    }
    FREPKIT_CHECK(failures, pieceCount == 2 && wrong == 0);
    FREPKIT_CHECK(failures, covered.size() == 16 * 15 * 14);
    FREPKIT_CHECK(failures, sourceRuns->Count == 2); // the object is built once, not per piece
  }

  // --- the model problem in small: Examples/homotopy5d.hf cut at (x4, x5) by name
  {
    const std::string file = std::string(FREPKIT_SOURCE_DIR) + "/Examples/homotopy5d.hf";
    vtkNew<vtkHyperFunSource> homotopy;
    homotopy->SetFileName(file.c_str());
    homotopy->SetCoordinateRange(0, -4, 4);
    homotopy->SetCoordinateRange(1, -4, 4);
    homotopy->SetCoordinateRange(2, -4, 4);
    vtkNew<vtkFRepSlice> cut;
    cut->SetInputConnection(homotopy->GetOutputPort());
    cut->SetFixedValueByName("x4", 0.25);
    cut->SetFixedValueByName("x5", 0.75);
    vtkNew<vtkFRepSampler> grid;
    grid->SetInputConnection(cut->GetOutputPort());
    grid->SetSampleDimensions(20, 20, 20); // bounds: the intervals [-4, 4]
    events->Observe(grid);
    events->Clear();
    grid->Update();
    FREPKIT_CHECK(failures, events->Errors == 0 && events->Warnings == 0);
    FREPKIT_CHECK(failures, grid->GetOutput()->GetOrigin()[0] == -4);
    vtkNew<vtkHyperFunSource> whole;
    whole->SetFileName(file.c_str());
    whole->Update();
    FREPKIT_CHECK(failures, whole->GetOutput()->GetDimension() == 5);
    FREPKIT_CHECK(failures,
      Mismatches(grid->GetOutput(), whole->GetOutput(), { 0, 1, 2 }, { { 3, 0.25 }, { 4, 0.75 } }) == 0);
    double range[2];
    grid->GetOutput()->GetPointData()->GetScalars()->GetRange(range);
    FREPKIT_CHECK(failures, range[0] < 0 && range[1] > 0); // a surface inside the box
  }

  return failures == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
