#include "vtkSpreadsheetLayout.h"

#include "vtkAppendPolyData.h"
#include "vtkCellArray.h"
#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkFloatArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkIntArray.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPartitionedDataSet.h"
#include "vtkPartitionedDataSetCollection.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkStringArray.h"
#include "vtkUnsignedCharArray.h"
#include "vtkVectorText.h"

#include <algorithm>
#include <array>
#include <vector>

vtkStandardNewMacro(vtkSpreadsheetLayout);

namespace
{

struct Cell
{
  vtkPolyData* poly = nullptr;
  std::array<int, 3> index{ 0, 0, 0 };
  std::string label;
  int linear = 0;
};

// A copy of `source` moved by `offset`, with the three point arrays every piece of the output
// has (so vtkAppendPolyData keeps them).
vtkSmartPointer<vtkPolyData> Moved(vtkPolyData* source,
  const double offset[3],
  int cellId,
  const unsigned char fallback[3])
{
  auto out = vtkSmartPointer<vtkPolyData>::New();
  const vtkIdType n = source->GetNumberOfPoints();
  vtkNew<vtkPoints> points;
  points->SetDataTypeToFloat();
  points->SetNumberOfPoints(n);
  double p[3];
  for (vtkIdType i = 0; i < n; ++i)
  {
    source->GetPoint(i, p);
    points->SetPoint(i, p[0] + offset[0], p[1] + offset[1], p[2] + offset[2]);
  }
  out->SetPoints(points);
  out->SetPolys(source->GetPolys());
  out->SetLines(source->GetLines());

  vtkNew<vtkUnsignedCharArray> colours;
  colours->SetName("Colors");
  colours->SetNumberOfComponents(3);
  colours->SetNumberOfTuples(n);
  vtkDataArray* in = source->GetPointData()->GetArray("Colors");
  for (vtkIdType i = 0; i < n; ++i)
  {
    for (int c = 0; c < 3; ++c)
    {
      colours->SetValue(
        3 * i + c, in ? static_cast<unsigned char>(in->GetComponent(i, c)) : fallback[c]);
    }
  }
  out->GetPointData()->SetScalars(colours);

  vtkNew<vtkFloatArray> normals;
  normals->SetName("Normals");
  normals->SetNumberOfComponents(3);
  normals->SetNumberOfTuples(n);
  vtkDataArray* inNormals = source->GetPointData()->GetNormals();
  for (vtkIdType i = 0; i < n; ++i)
  {
    double v[3] = { 0, -1, 0 };
    if (inNormals)
    {
      inNormals->GetTuple(i, v);
    }
    normals->SetTuple(i, v);
  }
  out->GetPointData()->SetNormals(normals);

  vtkNew<vtkIntArray> ids;
  ids->SetName("SpreadsheetCell");
  ids->SetNumberOfTuples(n);
  ids->FillValue(cellId);
  out->GetPointData()->AddArray(ids);
  return out;
}

} // namespace

//------------------------------------------------------------------------------
vtkSpreadsheetLayout::vtkSpreadsheetLayout() = default;
vtkSpreadsheetLayout::~vtkSpreadsheetLayout() = default;

//------------------------------------------------------------------------------
int vtkSpreadsheetLayout::FillInputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPartitionedDataSetCollection");
  return 1;
}

//------------------------------------------------------------------------------
int vtkSpreadsheetLayout::RequestData(vtkInformation*,
  vtkInformationVector** inputVector,
  vtkInformationVector* outputVector)
{
  auto* input = vtkPartitionedDataSetCollection::GetData(inputVector[0]);
  auto* output = vtkPolyData::GetData(outputVector);
  if (!input || !output)
  {
    return 1;
  }

  // The cells and the one box that holds them all.
  std::vector<Cell> cells;
  double box[6] = { VTK_DOUBLE_MAX,
    -VTK_DOUBLE_MAX,
    VTK_DOUBLE_MAX,
    -VTK_DOUBLE_MAX,
    VTK_DOUBLE_MAX,
    -VTK_DOUBLE_MAX };
  bool worldBounds = false;
  for (unsigned i = 0; i < input->GetNumberOfPartitionedDataSets(); ++i)
  {
    vtkPartitionedDataSet* pds = input->GetPartitionedDataSet(i);
    auto* poly = pds ? vtkPolyData::SafeDownCast(pds->GetPartition(0)) : nullptr;
    if (!poly)
    {
      continue;
    }
    Cell cell;
    cell.poly = poly;
    cell.linear = static_cast<int>(i);
    if (auto* index = vtkIntArray::SafeDownCast(poly->GetFieldData()->GetArray("CellIndex")))
    {
      for (int k = 0; k < 3; ++k)
      {
        cell.index[k] = std::max(0, index->GetValue(k));
      }
    }
    else
    {
      cell.index = { static_cast<int>(i), 0, 0 };
    }
    if (auto* label = vtkStringArray::SafeDownCast(poly->GetFieldData()->GetAbstractArray("Label")))
    {
      cell.label = label->GetNumberOfValues() > 0 ? label->GetValue(0) : std::string();
    }
    if (auto* wb = vtkDoubleArray::SafeDownCast(poly->GetFieldData()->GetArray("WorldBounds")))
    {
      if (wb->GetNumberOfComponents() == 6 && !worldBounds)
      {
        wb->GetTypedTuple(0, box);
        worldBounds = true;
      }
    }
    else if (!worldBounds && poly->GetNumberOfPoints() > 0)
    {
      double b[6];
      poly->GetBounds(b);
      for (int k = 0; k < 3; ++k)
      {
        box[2 * k] = std::min(box[2 * k], b[2 * k]);
        box[2 * k + 1] = std::max(box[2 * k + 1], b[2 * k + 1]);
      }
    }
    cells.push_back(cell);
  }
  if (cells.empty() || box[0] > box[1])
  {
    return 1; // nothing to lay out
  }
  const double size[3] = { std::max(box[1] - box[0], 1e-12),
    std::max(box[3] - box[2], 1e-12),
    std::max(box[5] - box[4], 1e-12) };
  // Rows also make room for the labels under the cells.
  const double labelRoom = this->Labels ? 1.6 * this->LabelHeight * size[2] : 0.0;
  const double step[3] = { size[0] * (1 + this->Spacing),
    size[1] * (1 + this->Spacing),
    size[2] * (1 + this->Spacing) + labelRoom };

  vtkNew<vtkAppendPolyData> append;
  const vtkIdType count = static_cast<vtkIdType>(cells.size());
  for (vtkIdType i = 0; i < count; ++i)
  {
    if (this->CheckAbort())
    {
      return 1;
    }
    const Cell& cell = cells[i];
    const double offset[3] = {
      cell.index[0] * step[0], cell.index[2] * step[1], -cell.index[1] * step[2]
    };
    append->AddInputData(Moved(cell.poly, offset, cell.linear, this->LabelColor));

    // The cell's frame: x from box[0] to box[1], z from box[4] to box[5], behind it (y max).
    const double margin = 0.04;
    const double x0 = box[0] - margin * size[0] + offset[0],
                 x1 = box[1] + margin * size[0] + offset[0];
    const double z0 = box[4] - margin * size[2] + offset[2],
                 z1 = box[5] + margin * size[2] + offset[2];
    const double y = box[3] + offset[1];
    if (this->Borders)
    {
      vtkNew<vtkPolyData> frame;
      vtkNew<vtkPoints> corners;
      corners->InsertNextPoint(x0, y, z0);
      corners->InsertNextPoint(x1, y, z0);
      corners->InsertNextPoint(x1, y, z1);
      corners->InsertNextPoint(x0, y, z1);
      frame->SetPoints(corners);
      vtkNew<vtkCellArray> lines;
      const vtkIdType loop[5] = { 0, 1, 2, 3, 0 };
      lines->InsertNextCell(5, loop);
      frame->SetLines(lines);
      const double zero[3] = { 0, 0, 0 };
      append->AddInputData(Moved(frame, zero, -1, this->LabelColor));
    }
    if (this->Labels && !cell.label.empty())
    {
      vtkNew<vtkVectorText> text;
      text->SetText(cell.label.c_str());
      text->Update();
      vtkPolyData* glyphs = text->GetOutput();
      double tb[6];
      glyphs->GetBounds(tb);
      const double height = this->LabelHeight * size[2];
      double scale = height / std::max(tb[3] - tb[2], 1e-12);
      scale = std::min(scale, 0.95 * (x1 - x0) / std::max(tb[1] - tb[0], 1e-12));
      // Text lies in its x-y plane: put its y along world z, centred under the frame.
      vtkNew<vtkPolyData> placed;
      vtkNew<vtkPoints> points;
      const double cx = 0.5 * (tb[0] + tb[1]);
      for (vtkIdType p = 0; p < glyphs->GetNumberOfPoints(); ++p)
      {
        double q[3];
        glyphs->GetPoint(p, q);
        points->InsertNextPoint(0.5 * (x0 + x1) + (q[0] - cx) * scale,
          box[2] + offset[1],
          z0 - 0.4 * height - (tb[3] - q[1]) * scale);
      }
      placed->SetPoints(points);
      placed->SetPolys(glyphs->GetPolys());
      const double zero[3] = { 0, 0, 0 };
      append->AddInputData(Moved(placed, zero, -1, this->LabelColor));
    }
    this->UpdateProgress(static_cast<double>(i + 1) / count);
  }
  append->Update();
  output->ShallowCopy(append->GetOutput());
  return 1;
}

//------------------------------------------------------------------------------
void vtkSpreadsheetLayout::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Spacing: " << this->Spacing << "\n";
  os << indent << "Borders: " << (this->Borders ? "On" : "Off") << "\n";
  os << indent << "Labels: " << (this->Labels ? "On" : "Off") << "\n";
  os << indent << "LabelHeight: " << this->LabelHeight << "\n";
  os << indent << "LabelColor: " << int(this->LabelColor[0]) << ", " << int(this->LabelColor[1])
     << ", " << int(this->LabelColor[2]) << "\n";
}
