// Image regression: a 3 x 2 spreadsheet of a 5-D model (a ball of radius 0.5 + 0.5 x4 moved
// along x by x5, coloured by x4) laid out by vtkSpreadsheetLayout with borders and labels,
// rendered by VTK with a parallel projection from -y.
#include "vtkMultimediaMapper.h"
#include "vtkMultimediaMapping.h"
#include "vtkSpreadsheetLayout.h"

#include "vtkHyperFunSource.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkNew.h"
#include "vtkPolyDataMapper.h"
#include "vtkRegressionTestImage.h"
#include "vtkRenderWindow.h"
#include "vtkRenderWindowInteractor.h"
#include "vtkRenderer.h"

int TestSpreadsheetLayoutRender(int argc, char* argv[])
{
  vtkNew<vtkHyperFunSource> source;
  source->SetModelText(R"(
    my_model(x[5], a[1])
    {
      r = 0.5 + 0.5 * x[4];
      my_model = r * r - (x[1] - x[5]) * (x[1] - x[5]) - x[2] * x[2] - x[3] * x[3];
    }
  )");
  vtkNew<vtkMultimediaMapping> mapping;
  mapping->LoadJSON(R"({
    "coordinates": {
      "x1": [{ "type": "world", "axis": "x", "range": [-1.5, 1.5] }],
      "x2": [{ "type": "world", "axis": "y", "range": [-1.5, 1.5] }],
      "x3": [{ "type": "world", "axis": "z", "range": [-1.5, 1.5] }],
      "x4": [{ "type": "spreadsheet", "axis": "columns", "values": [0, 0.5, 1] },
             { "type": "colour", "colormap": "viridis", "range": [0, 1] }],
      "x5": [{ "type": "spreadsheet", "axis": "rows", "values": [-0.4, 0.4] }]
    },
    "world": { "resolution": 48 }
  })");
  vtkNew<vtkMultimediaMapper> cells;
  cells->SetInputConnection(source->GetOutputPort());
  cells->SetMapping(mapping);
  vtkNew<vtkSpreadsheetLayout> layout;
  layout->SetInputConnection(cells->GetOutputPort());

  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputConnection(layout->GetOutputPort());
  mapper->SetScalarModeToUsePointFieldData();
  mapper->SelectColorArray("Colors");
  mapper->SetColorModeToDirectScalars();
  mapper->ScalarVisibilityOn();
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  vtkNew<vtkRenderer> renderer;
  renderer->AddActor(actor);
  renderer->SetBackground(1, 1, 1);
  vtkCamera* camera = renderer->GetActiveCamera();
  camera->ParallelProjectionOn();
  camera->SetPosition(0, -10, 0);
  camera->SetFocalPoint(0, 0, 0);
  camera->SetViewUp(0, 0, 1);
  renderer->ResetCamera();
  vtkNew<vtkRenderWindow> window;
  window->SetSize(450, 340);
  window->AddRenderer(renderer);
  vtkNew<vtkRenderWindowInteractor> interactor;
  interactor->SetRenderWindow(window);
  window->Render();
  const int result = vtkRegressionTestImage(window);
  if (result == vtkRegressionTester::DO_INTERACTOR)
  {
    interactor->Start();
  }
  return result == vtkRegressionTester::FAILED ? 1 : 0;
}
