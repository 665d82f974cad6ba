// main() for the original polygonizer hfp, built from the R package's sources without R: the
// package's entry point (hyperfun.cpp, an Rcpp export) does the same with R's argument vector.
#include <main.h> // hfp's, from the original's sources

#include <cstdio>
#include <exception>

CMainApp* edi = nullptr; // the original's global application object (declared in main.h)
int vn_t = 0;

int main(int argc, char** argv)
{
  try
  {
    edi = new CMainApp(argc, argv);
    vn_t = edi->init();
    delete edi;
    edi = nullptr;
    if (vn_t == 0)
    {
      std::fprintf(stderr, "hfp: Isosurface not generated.\n");
      return 1;
    }
    std::printf("\ntriangles: %d\n", vn_t);
    return 0;
  }
  catch (const std::exception& e)
  {
    std::fprintf(stderr, "hfp: %s\n", e.what());
    return 2;
  }
}
