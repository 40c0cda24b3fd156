"""Open an XDMF index with ParaView's XDMF3 reader (pvpython) and check what it sees.

usage: pvpython pv_check.py FILE.xdmf N TIMES ARRAYS
  N       particles in every snapshot, or one count per snapshot (comma-separated)
  TIMES   comma-separated snapshot times, e.g. 0.125,0.25
  ARRAYS  comma-separated point arrays with their components, e.g. vel:2,p:1

Exit status 0 when, at every time, the reader gives N points, N vertex cells (a particle set
without cells draws nothing) and, when N > 0, each array with its components; 1 otherwise.
"""
import os
import sys

from paraview import servermanager
from paraview.simple import Xdmf3ReaderS


def first_block(data):
    if data.IsA("vtkMultiBlockDataSet"):
        it = data.NewIterator()
        it.InitTraversal()
        return it.GetCurrentDataObject()
    return data


def main():
    # the XDMF library resolves the HDF5 files against the folder of an absolute path only
    path = os.path.abspath(sys.argv[1])
    times = [float(t) for t in sys.argv[3].split(",")]
    counts = [int(c) for c in sys.argv[2].split(",")]
    if len(counts) == 1:
        counts = counts * len(times)
    arrays = dict((a.split(":")[0], int(a.split(":")[1])) for a in sys.argv[4].split(","))
    reader = Xdmf3ReaderS(FileName=[path])
    reader.UpdatePipelineInformation()
    got_times = list(reader.TimestepValues)
    failures = []
    if got_times != times:
        failures.append("times %s, want %s" % (got_times, times))
    for t, n in zip(times, counts):
        reader.UpdatePipeline(t)
        ds = first_block(servermanager.Fetch(reader))
        pd = ds.GetPointData()
        print("t = %g: %d points, %d cells, arrays %s" % (
            t, ds.GetNumberOfPoints(), ds.GetNumberOfCells(),
            ", ".join("%s(%d)" % (pd.GetArrayName(i), pd.GetArray(i).GetNumberOfComponents())
                      for i in range(pd.GetNumberOfArrays()))))
        if ds.GetNumberOfPoints() != n or ds.GetNumberOfCells() != n:
            failures.append("t = %g: %d points and %d cells, want %d" % (
                t, ds.GetNumberOfPoints(), ds.GetNumberOfCells(), n))
        for name, ncomp in arrays.items() if n > 0 else []:
            a = pd.GetArray(name)
            if a is None or a.GetNumberOfTuples() != n or a.GetNumberOfComponents() != ncomp:
                failures.append("t = %g: array %s missing or not %d x %d" % (t, name, n, ncomp))
    for f in failures:
        print("FAIL: " + f)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
