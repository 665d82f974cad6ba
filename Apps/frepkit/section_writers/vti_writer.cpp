#include "vti_writer.h"

#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkStringArray.h>
#include <vtkXMLImageDataWriter.h>

#include <algorithm>
#include <stdexcept>
#include <string>

namespace frepkit
{

void write_vti(std::ostream& out, const SampledSection& section)
{
  vtkNew<vtkImageData> image;
  image->SetDimensions(static_cast<int>(section.samples[0]),
    static_cast<int>(section.samples[1]),
    static_cast<int>(section.samples[2]));
  image->SetOrigin(section.origin.data());
  image->SetSpacing(section.spacing.data());
  const vtkIdType count = static_cast<vtkIdType>(section.count());

  vtkNew<vtkDoubleArray> values;
  values->SetName("F");
  values->SetNumberOfTuples(count);
  std::copy(section.values.begin(), section.values.end(), values->GetPointer(0));
  image->GetPointData()->SetScalars(values);
  for (std::size_t j = 0; j < section.attributes.size(); ++j)
  {
    vtkNew<vtkDoubleArray> attribute;
    attribute->SetName(("s" + std::to_string(j + 1)).c_str());
    attribute->SetNumberOfTuples(count);
    std::copy(section.attributes[j].begin(), section.attributes[j].end(), attribute->GetPointer(0));
    image->GetPointData()->AddArray(attribute);
  }
  // Which model coordinates the image axes are.
  vtkNew<vtkStringArray> names;
  names->SetName("AxisNames");
  for (int k = 0; k < section.axes; ++k)
  {
    names->InsertNextValue(section.axis_names[static_cast<std::size_t>(k)]);
  }
  image->GetFieldData()->AddArray(names);

  vtkNew<vtkXMLImageDataWriter> writer;
  writer->SetInputData(image);
  writer->SetWriteToOutputString(true);
  writer->SetDataModeToBinary(); // inline base64: Debian 12's expat cannot read appended data back
  if (writer->Write() != 1)
  {
    throw std::runtime_error("vtkXMLImageDataWriter failed");
  }
  out << writer->GetOutputString();
}

} // namespace frepkit
