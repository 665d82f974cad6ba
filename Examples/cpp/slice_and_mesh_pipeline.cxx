// A VTK pipeline with FRepKit: read a 5-D HyperFun model, cut the 3-D cross-section
// x4 = 0.5, x5 = 0.25, mesh it (watertight, outward normals) and write it as VTK XML.
//
//   build/bin/frep_example_slice_and_mesh_pipeline Examples/homotopy5d.hf slice.vtp
#include "vtkFRepPolygonizer.h"
#include "vtkFRepSlice.h"
#include "vtkHyperFunSource.h"

#include <vtkNew.h>
#include <vtkPolyData.h>
#include <vtkXMLPolyDataWriter.h>

#include <iostream>

int main(int argc, char** argv)
{
  if (argc < 3)
  {
    std::cerr << "usage: " << argv[0] << " MODEL.hf OUT.vtp\n";
    return 1;
  }
  vtkNew<vtkHyperFunSource> reader; // the n-D object (my_model, else the first object)
  reader->SetFileName(argv[1]);
  for (int i = 0; i < 3; ++i)
  {
    reader->SetCoordinateRange(i, -4, 4); // x1..x3: the box the slice is meshed in
  }

  vtkNew<vtkFRepSlice> slice; // fix x4 and x5: a 3-D object with a smaller tape
  slice->SetInputConnection(reader->GetOutputPort());
  slice->SetFixedValueByName("x4", 0.5);
  slice->SetFixedValueByName("x5", 0.25);

  vtkNew<vtkFRepPolygonizer> mesher; // F = 0, culled, on all cores
  mesher->SetInputConnection(slice->GetOutputPort());
  mesher->SetSampleDimensions(96, 96, 96);

  vtkNew<vtkXMLPolyDataWriter> writer;
  writer->SetInputConnection(mesher->GetOutputPort());
  writer->SetFileName(argv[2]);
  writer->SetDataModeToBinary(); // inline: Debian 12's expat cannot read VTK 9.2's appended data
  if (!writer->Write())
  {
    return 1;
  }
  vtkPolyData* mesh = mesher->GetOutput();
  std::cout << "cross-section x4 = 0.5, x5 = 0.25: " << mesh->GetNumberOfPolys()
            << " triangles, " << mesh->GetNumberOfPoints() << " points -> " << argv[2] << "\n";
  return mesh->GetNumberOfPolys() > 0 ? 0 : 1;
}
