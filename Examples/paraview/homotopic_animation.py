"""The Homotopic Fun animation on ParaView's own time: Meta5D mapped by
Examples/paraview/meta5d-animation.json (x4, x5 dynamic along a closed path through the four
key shapes, 10 s at 24 fps, a quarter turn with x5). Multimedia Mapper in Frame mode publishes
the 240 frames as time steps; the animation scene (the GUI's animation toolbar) plays them.
Prints the time steps and, for --frames N frames spread over the loop, the frame's (x4, x5);
with --output saves frame_0000.png, ...

  pvpython Examples/paraview/homotopic_animation.py [--output DIR] [--frames 8]"""

import sys

sys.dont_write_bytecode = True  # no __pycache__ in the source tree
from frepkit_example import arguments, example_file
from paraview.simple import *  # noqa: F401,F403

args = arguments(__doc__, resolution=64, frames=8)
LoadPlugin(args.plugin, remote=False, ns=globals())

reader = HyperFunReader(FileName=example_file("homotopic", "meta5d.hf"), GenerateGeometry=0)
reader.CoordinateRanges = [-10, 10, -10, 10, -10, 10, 0, 1, 0, 1]
mapper = MultimediaMapper(Input=reader, OutputMode="Frame", Resolution=args.resolution,
                          MappingFileName=example_file("paraview", "meta5d-animation.json"))
mapper.UpdatePipelineInformation()
steps = list(mapper.TimestepValues)
scene = GetAnimationScene()
scene.UpdateAnimationUsingDataTimeSteps()
print("%d time steps, %.3f .. %.3f s; the animation scene has %d" %
      (len(steps), steps[0], steps[-1], len(GetTimeKeeper().TimestepValues)))

if args.output:
    view = GetActiveViewOrCreate("RenderView")
    view.ViewSize = [640, 480]
    view.OrientationAxesVisibility = 0
    shown = Show(mapper, view)
    ColorBy(shown, ("POINTS", "Colors"))
    shown.MapScalars = 0
    view.CameraPosition = [22.0, -30.0, 18.0]
    view.CameraFocalPoint = [0.0, 0.0, 0.0]
    view.CameraViewUp = [0.0, 0.0, 1.0]

count = max(1, args.frames)
for k in range(count):
    step = steps[(k * len(steps)) // count]
    scene.AnimationTime = step
    mapper.UpdatePipeline(step)
    frame = mapper.GetClientSideObject().GetOutputDataObject(0).GetPartition(0, 0)
    values = frame.GetFieldData().GetArray("CoordinateValues")
    print("t = %6.3f s: x4 = %.3f, x5 = %.3f, %d triangles" %
          (step, values.GetValue(3), values.GetValue(4), frame.GetNumberOfCells()))
    if args.output:
        Render(view)
        SaveScreenshot("%s/frame_%04d.png" % (args.output, k), view)
