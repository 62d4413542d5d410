"""What ParaView makes of a Crumple results file (docs/output-format.md, "Opening in ParaView").

Run with ParaView's Python (under a virtual display where there is none):

    xvfb-run -a -s "-screen 0 1280x1024x24 -noreset" pvpython check_paraview.py OUT/NAME.xdmf PICTURE.png \
        [--color FIELD] [--title TEXT]

(-noreset: see start_xvfb in run_paraview_check.py, which starts the server for the ctest.)

For each of ParaView's three XDMF readers it opens NAME.xdmf and steps through every frame. At each frame it
checks against NAME.h5, read with h5py:
  - the frame times, the node and element counts of every element kind;
  - the points ParaView draws are the frame's deformed positions (`coordinates`, the initial ones plus the
    displacement), opened as a user opens the file, with no filter;
  - every other dataset of the frame is an array in ParaView with the same values (so the same range), and every
    array ParaView shows comes from the file; the ids and part ids of the mesh too;
  - the stress of every element kind that has one is offered as a symmetric tensor (6 components, XX YY ZZ XY
    YZ XZ), beside its von Mises scalar;
  - the deleted elements are VTK ghost cells (vtkGhostType HIDDENCELL) and ParaView does not draw them: the
    cells of the rendered surface are the shells that are not deleted and the outer faces of the bricks that
    are not deleted.
Then it saves a picture of the last frame as the file opens (deformed, no filter), coloured by FIELD (default plastic_strain; part_id is
coloured by part, with the part titles of the file in the legend). Exit code 0 when all agrees, 1 otherwise.
"""
import argparse
import os
import sys

import h5py
import numpy as np
from paraview import servermanager
from paraview import simple as pv
from vtkmodules.util.numpy_support import vtk_to_numpy

HIDDEN_CELL = 32  # vtkDataSetAttributes::HIDDENCELL
GEOMETRY = "coordinates"  # the frame's node positions: the grid's points, not one of its arrays
TENSOR_COMPONENTS = ("XX", "YY", "ZZ", "XY", "YZ", "XZ")  # how ParaView names a symmetric tensor's components
KIND_OF_CELL = {9: "shell4", 5: "shell3", 12: "brick8"}  # VTK_QUAD, VTK_TRIANGLE, VTK_HEXAHEDRON
MESH_ARRAYS = {"element_id": "ids", "part_id": "part_id"}
BRICK_FACES = ((0, 3, 2, 1), (4, 5, 6, 7), (0, 1, 5, 4), (1, 2, 6, 5), (2, 3, 7, 6), (3, 0, 4, 7))
READERS = ("XDMFReader", "Xdmf3ReaderS", "Xdmf3ReaderT")

problems = []


def check(condition, text):
    if not condition:
        problems.append(text)
    return condition


def open_reader(name, xdmf):
    if name == "XDMFReader":
        return pv.XDMFReader(FileNames=[xdmf])
    return getattr(pv, name)(FileName=[xdmf])


def leaves(data):
    """The uniform grids of a reader's output (one per element kind present)."""
    if not data.IsA("vtkCompositeDataSet"):
        return [data]
    out = []
    it = data.NewIterator()
    it.InitTraversal()
    while not it.IsDoneWithTraversal():
        out.append(it.GetCurrentDataObject())
        it.GoToNextItem()
    return out


def frame_names(h5):
    return sorted(h5["frames"], key=int)


def expected_array(h5, frame, kind, name, cell):
    """The values NAME.h5 holds for the ParaView array `name` of a grid, or None."""
    if name == "node_id":
        return h5["mesh/node_ids"][:]
    if cell and name in MESH_ARRAYS:
        return h5[f"mesh/{kind}/{MESH_ARRAYS[name]}"][:]
    path = f"frames/{frame}/{kind}/{name}" if cell else f"frames/{frame}/{name}"
    return h5[path][:] if path in h5 else None


def compare_arrays(where, attributes, h5, frame, kind, cell):
    seen = set()
    for a in range(attributes.GetNumberOfArrays()):
        array = attributes.GetArray(a)
        name = array.GetName()
        seen.add(name)
        expected = expected_array(h5, frame, kind, name, cell)
        if not check(expected is not None, f"{where}: ParaView shows {name}, which NAME.h5 does not hold"):
            continue
        got = vtk_to_numpy(array).reshape(expected.shape)
        same = check(np.array_equal(got, expected), f"{where}: {name} differs from NAME.h5")
        if same and expected.size:
            low, high = expected.min(axis=0), expected.max(axis=0)
            ranges = [array.GetRange(c) for c in range(array.GetNumberOfComponents())]
            check(np.allclose(np.array(ranges).T, np.vstack([low, high]).reshape(2, -1), rtol=0, atol=0),
                  f"{where}: range of {name} {ranges} differs from NAME.h5 ({low}, {high})")
    group = h5[f"frames/{frame}/{kind}"] if cell else h5[f"frames/{frame}"]
    for name, item in group.items():
        if isinstance(item, h5py.Dataset) and name != GEOMETRY:
            check(name in seen, f"{where}: NAME.h5 holds {name}, which ParaView does not show")
    return seen


def check_grid(where, grid, h5, frame):
    kind = KIND_OF_CELL.get(grid.GetCellType(0)) if grid.GetNumberOfCells() else None
    if not check(kind is not None, f"{where}: a grid of unknown cells"):
        return None
    check(grid.GetNumberOfCells() == h5[f"mesh/{kind}/ids"].shape[0], f"{where}: {kind} cell count")
    check(grid.GetNumberOfPoints() == h5["mesh/node_ids"].shape[0], f"{where}: point count")
    if not check(GEOMETRY in h5[f"frames/{frame}"], f"{where}: NAME.h5's frame holds no deformed positions"):
        return kind
    points = vtk_to_numpy(grid.GetPoints().GetData())
    deformed = h5[f"frames/{frame}/{GEOMETRY}"][:]
    check(np.array_equal(points, deformed), f"{where}: the points drawn are not the frame's deformed positions")
    check(np.allclose(deformed, h5["mesh/coordinates"][:] + h5[f"frames/{frame}/displacement"][:], rtol=0,
                      atol=1e-9 * max(1.0, float(np.abs(deformed).max()))),
          f"{where}: the frame's positions are not the initial ones plus the displacement")
    compare_arrays(f"{where} {kind} cells", grid.GetCellData(), h5, frame, kind, True)
    compare_arrays(f"{where} {kind} nodes", grid.GetPointData(), h5, frame, kind, False)
    part_ids = set(h5["mesh/parts/ids"][:].tolist())
    shown_ids = set(vtk_to_numpy(grid.GetCellData().GetArray("part_id")).tolist())
    check(shown_ids <= part_ids, f"{where}: part ids {sorted(shown_ids)} not all in /mesh/parts/ids {sorted(part_ids)}")
    ghost = grid.GetCellGhostArray()
    if check(ghost is not None, f"{where}: {kind} has no ghost array ParaView recognises"):
        deleted = h5[f"frames/{frame}/{kind}/deleted"][:]
        check(np.array_equal(vtk_to_numpy(ghost), HIDDEN_CELL * deleted), f"{where}: {kind} ghost flags")
    return kind


def drawn_cells(h5, frame):
    """The cells of the surface ParaView draws: the shells not deleted, and the faces of the bricks not deleted
    that are on the outside of the whole brick mesh. (ParaView takes its surface of the bricks before it leaves
    out the hidden ones: a face between a live brick and a deleted one is not drawn.)"""
    count = 0
    for kind in ("shell4", "shell3"):
        if kind in h5["mesh"]:
            count += int(np.count_nonzero(h5[f"frames/{frame}/{kind}/deleted"][:] == 0))
    if "brick8" in h5["mesh"]:
        alive = h5[f"frames/{frame}/brick8/deleted"][:] == 0
        faces = {}
        for element, nodes in enumerate(h5["mesh/brick8/connectivity"][:]):
            for face in BRICK_FACES:
                faces.setdefault(tuple(sorted(nodes[list(face)])), []).append(element)
        count += sum(1 for owners in faces.values() if len(owners) == 1 and alive[owners[0]])
    return count


def check_reader(reader_name, xdmf, h5):
    reader = open_reader(reader_name, xdmf)
    times = list(np.atleast_1d(reader.TimestepValues))
    frames = frame_names(h5)
    expected_times = [float(h5["frames"][f].attrs["time"]) for f in frames]
    check(times == expected_times, f"{reader_name}: frame times {times} against {expected_times}")
    view = pv.CreateView("RenderView")
    view.ViewSize = [320, 240]
    shown = pv.Show(reader, view)
    kinds = set()
    for frame, time in zip(frames, expected_times):
        reader.UpdatePipeline(time)
        where = f"{reader_name} frame {frame} (t = {time:.6g})"
        for grid in leaves(servermanager.Fetch(reader)):
            kinds.add(check_grid(where, grid, h5, frame))
        view.ViewTime = time
        pv.Render(view)
        drawn = shown.GetRepresentedDataInformation().GetNumberOfCells()
        check(drawn == drawn_cells(h5, frame),
              f"{where}: ParaView draws {drawn} cells, the live elements make {drawn_cells(h5, frame)}")
    check_last_frame_as_opened(reader_name, reader, h5, frames[-1], expected_times[-1])
    present = {k for k in ("shell4", "shell3", "brick8") if k in h5["mesh"]}
    check(kinds == present, f"{reader_name}: grids {sorted(k for k in kinds if k)} against {sorted(present)}")
    pv.Delete(shown)
    pv.Delete(view)
    pv.Delete(reader)
    return len(frames)


def check_last_frame_as_opened(reader_name, reader, h5, frame, time):
    """What a user sees on opening the file, with no filter: the last frame's bounds are its deformed ones, and
    the stress is offered as a symmetric tensor beside its von Mises scalar."""
    reader.UpdatePipeline(time)
    where = f"{reader_name} last frame (t = {time:.6g})"
    if not check(GEOMETRY in h5[f"frames/{frame}"], f"{where}: NAME.h5's frame holds no deformed positions"):
        return
    deformed = h5[f"frames/{frame}/{GEOMETRY}"][:]
    expected = np.ravel(np.column_stack([deformed.min(axis=0), deformed.max(axis=0)]))
    shown = np.array(reader.GetDataInformation().GetBounds())
    check(np.allclose(shown, expected, rtol=0, atol=1e-9 * max(1.0, float(np.abs(expected).max()))),
          f"{where}: ParaView's bounds {shown} are not the deformed shape's {expected}")
    kinds = [k for k in ("shell4", "shell3", "brick8") if f"frames/{frame}/{k}/stress" in h5]
    if not kinds:
        return
    stress = reader.CellData["stress"]
    if check(stress is not None, f"{where}: ParaView offers no cell array stress"):
        names = tuple(stress.GetComponentName(c) for c in range(stress.GetNumberOfComponents()))
        check(names == TENSOR_COMPONENTS, f"{where}: stress is offered with components {names}, not a tensor's")
    check(reader.CellData["von_mises"] is not None, f"{where}: ParaView offers no von_mises beside the stress")


def part_annotations(h5):
    annotations = []
    for pid, title in zip(h5["mesh/parts/ids"][:], h5["mesh/parts/titles"][:]):
        title = title.decode() if isinstance(title, bytes) else str(title)
        annotations += [str(int(pid)), f"{int(pid)} {title}"]
    return annotations


def save_picture(xdmf, h5, picture, field, title):
    reader = pv.Xdmf3ReaderS(FileName=[xdmf])
    last = float(h5["frames"][frame_names(h5)[-1]].attrs["time"])
    view = pv.CreateView("RenderView")
    view.ViewSize = [1200, 800]
    view.OrientationAxesVisibility = 0
    view.UseColorPaletteForBackground = 0
    view.Background = [1.0, 1.0, 1.0]
    view.ViewTime = last
    shown = pv.Show(reader, view)
    shown.SetRepresentationType("Surface With Edges")
    shown.EdgeColor = [0.2, 0.2, 0.2]
    pv.ColorBy(shown, ("CELLS", field))
    lut = pv.GetColorTransferFunction(field)
    if field == "part_id":
        lut.InterpretValuesAsCategories = 1
        lut.Annotations = part_annotations(h5)
        lut.ApplyPreset("KAAMS", True)
    else:
        shown.RescaleTransferFunctionToDataRange(False, True)
        lut.ApplyPreset("Jet", True)
    shown.SetScalarBarVisibility(view, True)
    bar = pv.GetScalarBar(lut, view)
    bar.Title = field
    bar.ComponentTitle = ""
    bar.TitleColor = bar.LabelColor = [0.0, 0.0, 0.0]
    text = pv.Text(Text=f"{title}  t = {last:.4g}")
    label = pv.Show(text, view)
    label.Color = [0.0, 0.0, 0.0]
    label.WindowLocation = "Upper Center"
    view.CameraPosition = [1.0, -1.6, 1.1]
    view.CameraFocalPoint = [0.0, 0.0, 0.0]
    view.CameraViewUp = [0.0, 0.0, 1.0]
    view.ResetCamera()
    pv.Render(view)
    pv.SaveScreenshot(picture, view, ImageResolution=[1200, 800])


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("xdmf")
    parser.add_argument("picture")
    parser.add_argument("--color", default="plastic_strain")
    parser.add_argument("--title", default="")
    args = parser.parse_args()
    h5_path = args.xdmf[: -len(".xdmf")] + ".h5"
    with h5py.File(h5_path, "r") as h5:
        for reader_name in READERS:
            frames = check_reader(reader_name, args.xdmf, h5)
            print(f"{reader_name}: {frames} frames checked")
        save_picture(args.xdmf, h5, args.picture, args.color, args.title or h5.attrs["title"])
    print(f"picture: {args.picture}")
    for p in problems:
        print("MISMATCH:", p)
    print("ok" if not problems else f"{len(problems)} mismatches")
    return 0 if not problems else 1


if __name__ == "__main__":
    code = main()
    sys.stdout.flush()
    # Without a normal interpreter exit: the packaged ParaView's teardown of its OpenGL context under Xvfb can
    # fail (GLXBadContext) and turn a passing check into exit code 1.
    os._exit(code)
