// Smoke test of the stack: samples a VTK implicit function on all cores (STDThread SMP
// backend), contours it, writes the sampled slice as a PNG with OpenImageIO and reads it back,
// writes and reads a WAV with libsndfile, and uses Qt5. Fails loudly on any mismatch.
#include <OpenImageIO/imagebuf.h>
#include <QString>
#include <sndfile.h>
#include <vtkFlyingEdges3D.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPolyData.h>
#include <vtkSMPTools.h>
#include <vtkSampleFunction.h>
#include <vtkSphere.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

namespace
{

int failures = 0;

void check(bool condition, const char* what)
{
  std::printf("%s: %s\n", condition ? "PASS" : "FAIL", what);
  failures += condition ? 0 : 1;
}

} // namespace

int main(int argc, char** argv)
{
  const std::string dir = argc > 1 ? argv[1] : ".";

  // VTK: SMP backend, sampling and contouring.
  vtkSMPTools::SetBackend("STDThread");
  check(std::string(vtkSMPTools::GetBackend()) == "STDThread", "VTK SMP backend STDThread");
  vtkNew<vtkSphere> sphere;
  sphere->SetRadius(0.5);
  vtkNew<vtkSampleFunction> sample;
  sample->SetImplicitFunction(sphere);
  sample->SetModelBounds(-1, 1, -1, 1, -1, 1);
  sample->SetSampleDimensions(32, 32, 32);
  vtkNew<vtkFlyingEdges3D> contour;
  contour->SetInputConnection(sample->GetOutputPort());
  contour->SetValue(0, 0.0);
  contour->Update();
  check(contour->GetOutput()->GetNumberOfPolys() > 100, "VTK sample + flying edges");

  // OpenImageIO: write the z = 16 slice as an 8-bit PNG, read it back.
  vtkImageData* image = sample->GetOutput();
  const int n = 32;
  std::vector<unsigned char> pixels(n * n);
  for (int j = 0; j < n; ++j)
  {
    for (int i = 0; i < n; ++i)
    {
      pixels[j * n + i] = image->GetScalarComponentAsDouble(i, j, 16, 0) < 0 ? 255 : 0;
    }
  }
  const std::string png = dir + "/stack_smoke.png";
  OIIO::ImageBuf out(OIIO::ImageSpec(n, n, 1, OIIO::TypeDesc::UINT8), pixels.data());
  check(out.write(png), "OpenImageIO writes PNG");
  OIIO::ImageBuf in(png);
  float centre[1] = { 0 };
  in.getpixel(n / 2, n / 2, centre);
  check(in.spec().width == n && centre[0] > 0.99f, "OpenImageIO reads the PNG back");

  // libsndfile: one second of a 440 Hz tone.
  const std::string wav = dir + "/stack_smoke.wav";
  SF_INFO info{};
  info.samplerate = 8000;
  info.channels = 1;
  info.format = SF_FORMAT_WAV | SF_FORMAT_PCM_16;
  SNDFILE* file = sf_open(wav.c_str(), SFM_WRITE, &info);
  check(file != nullptr, "libsndfile opens a WAV for writing");
  if (file)
  {
    std::vector<double> tone(8000);
    for (std::size_t i = 0; i < tone.size(); ++i)
    {
      tone[i] = 0.5 * std::sin(2 * M_PI * 440 * static_cast<double>(i) / 8000);
    }
    sf_write_double(file, tone.data(), static_cast<sf_count_t>(tone.size()));
    sf_close(file);
    SF_INFO read_info{};
    SNDFILE* back = sf_open(wav.c_str(), SFM_READ, &read_info);
    check(back && read_info.frames == 8000, "libsndfile reads the WAV back");
    if (back)
    {
      sf_close(back);
    }
  }

  // Qt5.
  check(QString("FRep%1").arg("Kit") == "FRepKit", "Qt5 core");

  return failures == 0 ? 0 : 1;
}
