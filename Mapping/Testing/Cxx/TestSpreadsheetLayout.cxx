// vtkSpreadsheetLayout: the cells of a 2 x 2 spreadsheet (a 5-D model mapped with x4 on the
// columns and x5 on the rows) become one vtkPolyData: every cell's triangles are there, moved
// to its grid place (columns along +x, rows down along -z), with borders and labels; the
// "SpreadsheetCell" array says which cell each point came from.
#include "FRepKitSourcesTestHelpers.h"

#include "vtkMultimediaMapper.h"
#include "vtkMultimediaMapping.h"
#include "vtkSpreadsheetLayout.h"

#include "vtkHyperFunSource.h"

#include "vtkDataArray.h"
#include "vtkIntArray.h"
#include "vtkNew.h"
#include "vtkPartitionedDataSet.h"
#include "vtkPartitionedDataSetCollection.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"

#include <cmath>
#include <set>

int TestSpreadsheetLayout(int, char*[])
{
  int failures = 0;
  vtkNew<vtkHyperFunSource> source;
  source->SetModelText(R"(
    my_model(x[5], a[1])
    {
      -- a ball of radius 0.5 + 0.5 x4, moved along x by x5
      r = 0.5 + 0.5 * x[4];
      my_model = r * r - (x[1] - x[5]) * (x[1] - x[5]) - x[2] * x[2] - x[3] * x[3];
    }
  )");
  vtkNew<vtkMultimediaMapping> mapping;
  FREPKIT_CHECK(failures, mapping->LoadJSON(R"({
    "coordinates": {
      "x1": [{ "type": "world", "axis": "x", "range": [-1.5, 1.5] }],
      "x2": [{ "type": "world", "axis": "y", "range": [-1.5, 1.5] }],
      "x3": [{ "type": "world", "axis": "z", "range": [-1.5, 1.5] }],
      "x4": [{ "type": "spreadsheet", "axis": "columns", "values": [0, 1] }],
      "x5": [{ "type": "spreadsheet", "axis": "rows", "values": [0, 0.25] }]
    },
    "world": { "resolution": 32 }
  })"));
  vtkNew<vtkMultimediaMapper> mapper;
  mapper->SetInputConnection(source->GetOutputPort());
  mapper->SetMapping(mapping);
  mapper->Update();
  auto* cells = mapper->GetOutput();
  FREPKIT_CHECK(failures, cells->GetNumberOfPartitionedDataSets() == 4);
  vtkIdType cellTriangles = 0;
  for (unsigned i = 0; i < cells->GetNumberOfPartitionedDataSets(); ++i)
  {
    cellTriangles += vtkPolyData::SafeDownCast(cells->GetPartitionedDataSet(i)->GetPartition(0))
                       ->GetNumberOfPolys();
  }

  vtkNew<vtkSpreadsheetLayout> layout;
  layout->SetInputConnection(mapper->GetOutputPort());
  FREPKIT_CHECK(
    failures, layout->GetSpacing() == 0.15 && layout->GetBorders() && layout->GetLabels());
  layout->LabelsOff();
  layout->BordersOff();
  layout->Update();
  vtkPolyData* sheet = layout->GetOutput();
  FREPKIT_CHECK(failures, sheet->GetNumberOfPolys() == cellTriangles);
  FREPKIT_CHECK(failures, sheet->GetNumberOfLines() == 0);
  double b[6];
  sheet->GetBounds(b);
  // the world box is 3 wide: the right column starts 3 * 1.15 to the right, and the lower row
  // 3 * 1.15 lower
  std::cout << "bounds " << b[0] << " " << b[1] << " " << b[2] << " " << b[3] << " " << b[4] << " "
            << b[5] << "\n";
  FREPKIT_CHECK(failures, std::abs(b[1] - (3.45 + 1.25)) < 0.05); // x5 = 0.25 moves the ball right
  FREPKIT_CHECK(failures, std::abs(b[4] - (-3.45 - 1.0)) < 0.05); // ball of radius 1, lower row
  auto* ids = vtkIntArray::SafeDownCast(sheet->GetPointData()->GetArray("SpreadsheetCell"));
  FREPKIT_CHECK(failures, ids != nullptr);
  std::set<int> seen;
  for (vtkIdType i = 0; ids && i < ids->GetNumberOfTuples(); ++i)
  {
    seen.insert(ids->GetValue(i));
  }
  FREPKIT_CHECK(failures, seen == std::set<int>({ 0, 1, 2, 3 }));
  FREPKIT_CHECK(failures, sheet->GetPointData()->GetArray("Colors") != nullptr);
  FREPKIT_CHECK(failures, sheet->GetPointData()->GetNormals() != nullptr);

  // With borders and labels: 4 frames of lines and text polygons in the label colour.
  layout->LabelsOn();
  layout->BordersOn();
  layout->Update();
  FREPKIT_CHECK(failures, layout->GetOutput()->GetNumberOfLines() == 4);
  FREPKIT_CHECK(failures, layout->GetOutput()->GetNumberOfPolys() > cellTriangles);
  layout->Print(std::cout);
  return failures == 0 ? 0 : 1;
}
