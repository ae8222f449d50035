# Mean along-slope velocity of the layer of scene.toml against time, and its least-squares
# acceleration from START on: acceleration.py CASE THETA_DEG OUTPUT_INTERVAL START
import sys, glob, vtk, numpy as np
from vtk.util.numpy_support import vtk_to_numpy as v2n
th = np.radians(float(sys.argv[2])); t_dir = np.array([np.cos(th), -np.sin(th)])
n_dir = np.array([np.sin(th), np.cos(th)])
files = sorted(glob.glob(sys.argv[1] + "/output/release_points_*.vtu"))
r = vtk.vtkXMLUnstructuredGridReader()
out = []
for i, f in enumerate(files):
    r.SetFileName(f); r.Update(); g = r.GetOutput()
    x = v2n(g.GetPoints().GetData())[:, :2]; v = v2n(g.GetPointData().GetArray("velocity"))[:, :2]
    m = v2n(g.GetPointData().GetArray("mass"))
    vt = v @ t_dir; h = x @ n_dir
    if i == 0: x0 = x.copy()
    s = (x - x0) @ t_dir
    out.append((i * float(sys.argv[3]), np.sum(m * vt) / m.sum(), np.sum(m*s)/m.sum(), np.percentile(h, 99)))
for t, v, s, h in out: print(f"t {t:.2f} mean v_t {v:.3f}  mean slid {s:.3f}  top {h:.3f}")
ts = np.array([o[0] for o in out]); vs = np.array([o[1] for o in out])
k = ts >= float(sys.argv[4]); print("accel fit", np.polyfit(ts[k], vs[k], 1)[0])
