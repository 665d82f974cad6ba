// Uses an installed FRepKit (find_package(FRepKit)): evaluates a HyperFun model at one point with
// the engine, then meshes its cross-section x4 = 0.5, x5 = 0.25 in a VTK pipeline.
//
//   frepkit_consumer MODEL.hf OUT.vtp [x1 x2 x3 x4 x5]
#include "Compiler/model.h"
#include "Eval/point_evaluator.h"
#include "Compiler/load_model.h"

#include "vtkFRepPolygonizer.h"
#include "vtkFRepSlice.h"
#include "vtkHyperFunSource.h"

#include <vtkNew.h>
#include <vtkPolyData.h>
#include <vtkXMLPolyDataWriter.h>

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <sstream>
#include <vector>

int main(int argc, char** argv)
{
  if (argc < 3)
  {
    std::cerr << "usage: " << argv[0] << " MODEL.hf OUT.vtp [x1 x2 ...]\n";
    return 1;
  }

  // The engine: load (read, parse, choose my_model, compile), evaluate F at one point.
  const frep::LoadedModel compiled = frep::load_model(frep::ModelSource::file(argv[1]));
  if (!compiled.ok())
  {
    std::cerr << compiled.message();
    return 1;
  }
  std::vector<double> point;
  for (int i = 3; i < argc; ++i)
  {
    point.push_back(std::strtod(argv[i], nullptr));
  }
  point.resize(static_cast<std::size_t>(compiled.model->x_dim()), 0.0);
  frep::PointEvaluator evaluator(compiled.model->tape());
  std::printf("F = %.17g\n", evaluator.value(point));

  // The VTK pipeline: n-D object -> 3-D slice -> mesh -> .vtp file.
  vtkNew<vtkHyperFunSource> source;
  source->SetFileName(argv[1]);
  for (int i = 0; i < 3; ++i)
  {
    source->SetCoordinateRange(i, -4, 4);
  }
  vtkNew<vtkFRepSlice> slice;
  slice->SetInputConnection(source->GetOutputPort());
  slice->SetFixedValueByName("x4", 0.5);
  slice->SetFixedValueByName("x5", 0.25);
  vtkNew<vtkFRepPolygonizer> mesher;
  mesher->SetInputConnection(slice->GetOutputPort());
  mesher->SetSampleDimensions(64, 64, 64);
  vtkNew<vtkXMLPolyDataWriter> writer;
  writer->SetInputConnection(mesher->GetOutputPort());
  writer->SetFileName(argv[2]);
  writer->SetDataModeToBinary();
  if (!writer->Write())
  {
    return 1;
  }
  const vtkIdType triangles = mesher->GetOutput()->GetNumberOfPolys();
  std::printf("triangles = %lld -> %s\n", static_cast<long long>(triangles), argv[2]);
  return triangles > 0 ? 0 : 1;
}
