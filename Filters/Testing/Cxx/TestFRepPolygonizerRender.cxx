// Image regression: a CSG model with s[] colours meshed by vtkFRepPolygonizer and rendered.
#include "vtkFRepPolygonizer.h"
#include "vtkHyperFunSource.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkNew.h"
#include "vtkPolyDataMapper.h"
#include "vtkRegressionTestImage.h"
#include "vtkRenderWindow.h"
#include "vtkRenderWindowInteractor.h"
#include "vtkRenderer.h"

int TestFRepPolygonizerRender(int argc, char* argv[])
{
  vtkNew<vtkHyperFunSource> source;
  source->SetModelText("my_model(x[3], a[1], s[1]) {"
                       " array v[3]; v = [-6, -6, -6];"
                       " cube = hfBlock(x, v, 12, 12, 12);"
                       " ball = 56 - x[1]^2 - x[2]^2 - x[3]^2;"
                       " rod = 4 - x[1]^2 - x[2]^2;"
                       " s[1] = x[3];"
                       " my_model = (cube & ball) \\ rod; }");
  vtkNew<vtkFRepPolygonizer> mesher;
  mesher->SetInputConnection(source->GetOutputPort());
  mesher->SetModelBounds(-7, 7, -7, 7, -7, 7);
  mesher->SetSampleDimensions(96, 96, 96);

  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputConnection(mesher->GetOutputPort());
  mapper->SetScalarModeToUsePointFieldData();
  mapper->SelectColorArray("s");
  mapper->SetScalarRange(-7, 7);
  mapper->ScalarVisibilityOn();
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  vtkNew<vtkRenderer> renderer;
  renderer->AddActor(actor);
  renderer->SetBackground(0.1, 0.1, 0.15);
  renderer->GetActiveCamera()->SetPosition(20, -30, 25);
  renderer->GetActiveCamera()->SetViewUp(0, 0, 1);
  renderer->ResetCamera();
  vtkNew<vtkRenderWindow> window;
  window->SetSize(300, 300);
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
