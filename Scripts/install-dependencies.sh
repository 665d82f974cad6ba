#!/usr/bin/env bash
# Installs every Debian 12 package FRepKit builds, tests and runs with, in one apt-get line.
# The first block is the stack checked in a fresh debootstrap chroot (../shared/DESIGN.md,
# "The stack on Debian 12"): ParaView 5.11 and its bundled VTK, Qt5, OpenImageIO, ffmpeg, Xvfb.
# The second block is what the engine, the tools and the tests add.
# Runs apt as root directly, or through sudo when the caller is not root.
set -euo pipefail

packages=(
  # ParaView / VTK / Qt / media stack (DESIGN.md)
  paraview paraview-dev python3-paraview
  qtbase5-dev libqt5opengl5-dev libqt5svg5-dev qttools5-dev qtxmlpatterns5-dev-tools
  libopenimageio-dev openimageio-tools libopencv-core-dev libsndfile1-dev ffmpeg xvfb xauth
  libutfcpp-dev libavcodec-dev libavformat-dev libavutil-dev libswscale-dev libopenmpi-dev
  liblz4-dev libdouble-conversion-dev libtheora-dev libglew-dev libtiff-dev libfreetype-dev
  libpng-dev libjpeg-dev libx11-dev libgl-dev libexpat1-dev zlib1g-dev liblzma-dev
  # the headless renderer's labels (Multimedia/Render: DejaVu Sans)
  fonts-dejavu-core
  # mpiexec for the ParaView plug-in's distributed test (mpiexec -n 2 pvbatch)
  openmpi-bin
  # the Python wrapping (cmake/FRepKitPython.cmake): Python's headers for VTK's wrapped modules,
  # numpy for vtkmodules.util.numpy_support and the Python tests
  python3-dev python3-numpy
  # toolchain, engine, command line, tests and benchmarks
  build-essential cmake pkg-config git
  # the Debian package (cpack -G DEB): dpkg-shlibdeps/dpkg-deb, and file, which CPack uses to
  # find the binaries whose libraries become the package's Depends
  dpkg-dev file
  libcli11-dev nlohmann-json3-dev libgtest-dev libgmock-dev libbenchmark-dev
  # the durable-write test traces fsync/rename (Testing/Apps/frepkit_durable_writes_test.sh);
  # FRepStudio's leak check preloads gcc's LeakSanitizer runtime (liblsan.so.0)
  strace liblsan0
  # the sanitizer build and the fuzz harnesses (ctest -R Build.SanitizersAndFuzzing): clang 14,
  # its runtime libraries (ASan, UBSan, libFuzzer), llvm-profdata/llvm-cov for coverage by hand
  clang libclang-rt-14-dev llvm
)

if [ "$(id -u)" -eq 0 ]; then
  run_as_root=()
else
  run_as_root=(sudo)
fi

export DEBIAN_FRONTEND=noninteractive
"${run_as_root[@]}" apt-get update
"${run_as_root[@]}" apt-get install -y --no-install-recommends "${packages[@]}"
