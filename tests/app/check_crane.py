#!/usr/bin/python3
"""Checks a run of meshes/two_arm_crane.yaml (and, given a second, the same run on another
rank count):
  - the joints hold: the point each side carries (/samples/joint_links) is the same for the
    three hinges and the two clamps, within 1e-8 m, and a clamp's point is its pipe node;
  - the links start at the bodies' nodes (arm 1, arm 2, holder);
  - the reactions written are the ground's (an output check: the same law at the sampled
    state): at each pipe node below the ground the normal part max(0, -k z - c dz/dt)
    (k = 1e5 N/m, c = 200 N s/m), never a pull, and along the ground at most 0.3 times it;
  - the pipe touched the ground (the crane lowers it there);
  - the other run's positions, links and reactions agree (1e-8 m, 1e-4 N).
Usage: check_crane.py OUT.h5 [OTHER.h5]
"""
import sys

import h5py
import numpy as np

K, C, MU = 1.0e5, 200.0, 0.3
BODIES = ["arm 1", "arm 2", "holder"]
# The scene's joints in order: (body A, body B or None, the pipe node id B is, if any).
JOINTS = [("arm 1", None, None), ("arm 2", "arm 1", None), ("holder", "arm 2", None),
          ("holder", None, 11), ("holder", None, 12)]


def read(path):
    with h5py.File(path, "r") as f:
        assert f.attrs["status"] == "complete", f.attrs["status"]
        rows = {n: int(f["bodies/" + n].attrs["index"]) for n in BODIES}
        return {"t": f["time"][:], "x": f["samples/positions"][:],
                "v": f["samples/velocities"][:], "links": f["samples/joint_links"][:],
                "reaction": f["samples/reaction_force"][:], "ids": f["mesh/node_ids"][:],
                "body_nodes": f["mesh/body_nodes"][:], "support": f["mesh/support_nodes"][:],
                "rows": rows}


r = read(sys.argv[1])
x, v, links, reaction = r["x"], r["v"], r["links"], r["reaction"]
node_of_id = {int(i): k for k, i in enumerate(r["ids"])}
gap = np.abs(links[:, :, 1] - links[:, :, 2]).max()
start = 0.0
for j, (a, b, pipe_node) in enumerate(JOINTS):
    start = max(start, np.abs(links[:, j, 0] - x[:, r["body_nodes"][r["rows"][a]]]).max())
    if b is not None:
        start = max(start, np.abs(links[:, j, 3] - x[:, r["body_nodes"][r["rows"][b]]]).max())
    if pipe_node is not None:
        start = max(start, np.abs(links[:, j, 2] - x[:, node_of_id[pipe_node]]).max())
print("joints: carried points together within %.3g m; links from their nodes within %.3g m" %
      (gap, start))
assert gap < 1e-8 and start < 1e-12, (gap, start)

# The ground's reaction on each pipe node against its law.
pipe = r["support"]
z, dz = x[:, pipe, 2], v[:, pipe, 2]
normal, along = reaction[:, :, 2], np.hypot(reaction[:, :, 0], reaction[:, :, 1])
law = np.where(z < 0.0, np.maximum(0.0, -K * z - C * dz), 0.0)
law_error = np.abs(normal - law).max()
friction_excess = (along - MU * normal).max()
print("ground: largest total push %.1f N, normal force within %.3g N of its law, friction "
      "at most %.3g N beyond 0.3 times it" % (normal.sum(axis=1).max(), law_error,
                                               friction_excess))
assert normal.min() >= 0.0, "the ground pulls"
assert law_error < 1e-6 * max(1.0, normal.max()), law_error
assert friction_excess < 1e-9 * max(1.0, normal.max()), friction_excess
assert normal.sum(axis=1).max() > 10.0, "the pipe never touched the ground"

if len(sys.argv) > 2:
    o = read(sys.argv[2])
    assert o["t"].shape == r["t"].shape
    dx, dl = np.abs(x - o["x"]).max(), np.abs(links - o["links"]).max()
    dr = np.abs(reaction - o["reaction"]).max()
    print("against %s: positions %.3g m, links %.3g m, reactions %.3g N" %
          (sys.argv[2], dx, dl, dr))
    assert dx < 1e-8 and dl < 1e-8 and dr < 1e-4
print("two-arm crane: OK")
