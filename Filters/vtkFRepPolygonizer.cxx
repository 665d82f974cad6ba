#include "vtkFRepPolygonizer.h"

#include "vtkFRepObject.h"

#include "vtkCellArray.h"
#include "vtkFloatArray.h"
#include "vtkIdTypeArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkStreamingDemandDrivenPipeline.h"

#include "Mesh/surface.h"

#include <thread>

vtkStandardNewMacro(vtkFRepPolygonizer);

//------------------------------------------------------------------------------
// The mesher's points, cells, normals and attributes as vtkPolyData arrays.
void vtkFRepPolygonizer::ConvertSurface(
  const frep::mesh::Surface& surface, int precision, vtkPolyData* output)
{
  const auto count = static_cast<vtkIdType>(surface.point_count());
  vtkNew<vtkPoints> points;
  points->SetDataType(precision == vtkAlgorithm::DOUBLE_PRECISION ? VTK_DOUBLE : VTK_FLOAT);
  points->SetNumberOfPoints(count);
  for (vtkIdType p = 0; p < count; ++p)
  {
    points->SetPoint(p, &surface.points[3 * static_cast<std::size_t>(p)]);
  }
  output->SetPoints(points);

  const int per_cell = surface.dimension == 3 ? 3 : 2;
  const auto cells = static_cast<vtkIdType>(surface.cell_count());
  vtkNew<vtkIdTypeArray> offsets;
  offsets->SetNumberOfValues(cells + 1);
  for (vtkIdType c = 0; c <= cells; ++c)
  {
    offsets->SetValue(c, c * per_cell);
  }
  vtkNew<vtkIdTypeArray> connectivity;
  connectivity->SetNumberOfValues(static_cast<vtkIdType>(surface.cells.size()));
  for (std::size_t k = 0; k < surface.cells.size(); ++k)
  {
    connectivity->SetValue(static_cast<vtkIdType>(k), surface.cells[k]);
  }
  vtkNew<vtkCellArray> array;
  array->SetData(offsets, connectivity);
  if (surface.dimension == 3)
  {
    output->SetPolys(array);
  }
  else
  {
    output->SetLines(array);
  }

  if (!surface.normals.empty())
  {
    vtkNew<vtkFloatArray> normals;
    normals->SetName("Normals");
    normals->SetNumberOfComponents(3);
    normals->SetNumberOfTuples(count);
    std::copy(surface.normals.begin(), surface.normals.end(), normals->GetPointer(0));
    output->GetPointData()->SetNormals(normals);
  }
  if (!surface.attributes.empty() && surface.attribute_count > 0)
  {
    vtkNew<vtkFloatArray> s;
    s->SetName("s");
    s->SetNumberOfComponents(surface.attribute_count);
    s->SetNumberOfTuples(count);
    std::copy(surface.attributes.begin(), surface.attributes.end(), s->GetPointer(0));
    output->GetPointData()->AddArray(s);
  }
}

//------------------------------------------------------------------------------
vtkFRepPolygonizer::vtkFRepPolygonizer() = default;
vtkFRepPolygonizer::~vtkFRepPolygonizer() = default;

//------------------------------------------------------------------------------
int vtkFRepPolygonizer::FillInputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkFRepObject");
  return 1;
}

//------------------------------------------------------------------------------
int vtkFRepPolygonizer::RequestInformation(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  // Each piece polygonises its own slab of cells.
  outputVector->GetInformationObject(0)->Set(CAN_HANDLE_PIECE_REQUEST(), 1);
  return 1;
}

//------------------------------------------------------------------------------
int vtkFRepPolygonizer::RequestData(vtkInformation*, vtkInformationVector** inputVector,
  vtkInformationVector* outputVector)
{
  vtkFRepObject* input = vtkFRepObject::GetData(inputVector[0]);
  vtkInformation* outInfo = outputVector->GetInformationObject(0);
  vtkPolyData* output = vtkPolyData::GetData(outInfo);
  this->EvaluatedSamples = this->CulledBoxes = this->FailedSamples = 0;
  if (!input || !input->HasModel())
  {
    // An upstream error (already reported there) leaves nothing to mesh: no cascade.
    vtkDebugMacro("the input has no model: empty output");
    return 1;
  }
  const vtkFRepObject::EvaluationDescription description = input->GetEvaluationDescription();
  const int dimension = input->GetDimension();
  if (dimension != 2 && dimension != 3)
  {
    vtkErrorMacro("the object has " << dimension
                                    << " free coordinates: a surface needs 3, a contour 2 "
                                       "(fix the others with vtkFRepSlice)");
    return 1;
  }

  frep::GridSpec grid;
  for (int a = 0; a < dimension; ++a)
  {
    const bool bounds_set = this->ModelBounds[2 * a] <= this->ModelBounds[2 * a + 1];
    grid.axes.push_back({ bounds_set ? this->ModelBounds[2 * a] : description.Ranges[a][0],
      bounds_set ? this->ModelBounds[2 * a + 1] : description.Ranges[a][1],
      this->SampleDimensions[a] });
  }

  frep::mesh::ExtractOptions options;
  options.iso = this->IsoValue;
  options.cap_boundary = this->CapBoundary != 0;
  options.normals = this->ComputeNormals != 0;
  options.attributes = this->ComputeAttributes != 0;
  options.cull = this->Culling != 0;
  options.refine_steps = this->RefinementSteps;
  options.max_samples = this->MaximumNumberOfSamples;
  options.threads = this->NumberOfThreads;

  // A piece is a slab of cells along the last axis: the samples from its first cell's to its
  // last cell's far side (neighbouring pieces share a plane of samples, as VTK extents do).
  const int piece = outInfo->Get(vtkStreamingDemandDrivenPipeline::UPDATE_PIECE_NUMBER());
  const int pieces = outInfo->Get(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_PIECES());
  frep::GridAxis& slab = grid.axes.back();
  if (pieces > 1 && slab.samples >= 2)
  {
    const std::int64_t cells = slab.samples - 1;
    const std::int64_t begin = cells * piece / pieces;
    const std::int64_t end = cells * (piece + 1) / pieces;
    if (begin == end)
    {
      return 1; // more pieces than cells: this one is empty
    }
    slab.begin = begin;
    slab.end = end + 1;
  }

  // Progress goes out on this thread only (observers are not thread-safe); abort is an atomic.
  const std::thread::id caller = std::this_thread::get_id();
  options.progress = [this, caller](double fraction)
  {
    if (std::this_thread::get_id() == caller)
    {
      this->UpdateProgress(fraction);
      return !this->CheckAbort();
    }
    return !this->GetAbortExecute();
  };

  const frep::mesh::ExtractResult result =
    dimension == 3 ? frep::mesh::extract_surface(description.Tape, grid, options)
                   : frep::mesh::extract_contour(description.Tape, grid, options);
  // Only this thread's progress calls look at the observers' abort request; when the other
  // workers finish the grid before the next such call, the extraction completes although an
  // abort was asked for. Aborted means empty, whoever noticed it.
  if (result.cancelled || this->GetAbortExecute())
  {
    return 1; // aborted: empty output
  }
  if (!result.error.empty())
  {
    vtkErrorMacro(<< result.error);
    return 1;
  }
  this->EvaluatedSamples = result.statistics.samples;
  this->CulledBoxes = result.statistics.boxes_culled;
  this->FailedSamples = result.statistics.failed_samples;
  if (result.statistics.failed_samples > 0)
  {
    vtkWarningMacro(<< result.statistics.failed_samples
                    << " grid points raised a run-time error in the model and count as outside "
                       "(frepkit eval on such a point gives the message and position)");
  }
  ConvertSurface(result.surface, this->OutputPointsPrecision, output);
  return 1;
}

//------------------------------------------------------------------------------
void vtkFRepPolygonizer::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "ModelBounds: (" << this->ModelBounds[0] << ", " << this->ModelBounds[1]
     << ", " << this->ModelBounds[2] << ", " << this->ModelBounds[3] << ", "
     << this->ModelBounds[4] << ", " << this->ModelBounds[5] << ")\n";
  os << indent << "SampleDimensions: (" << this->SampleDimensions[0] << ", "
     << this->SampleDimensions[1] << ", " << this->SampleDimensions[2] << ")\n";
  os << indent << "IsoValue: " << this->IsoValue << "\n";
  os << indent << "CapBoundary: " << this->CapBoundary << "\n";
  os << indent << "ComputeNormals: " << this->ComputeNormals << "\n";
  os << indent << "ComputeAttributes: " << this->ComputeAttributes << "\n";
  os << indent << "Culling: " << this->Culling << "\n";
  os << indent << "RefinementSteps: " << this->RefinementSteps << "\n";
  os << indent << "MaximumNumberOfSamples: " << this->MaximumNumberOfSamples << "\n";
  os << indent << "NumberOfThreads: " << this->NumberOfThreads << "\n";
  os << indent << "OutputPointsPrecision: " << this->OutputPointsPrecision << "\n";
}
