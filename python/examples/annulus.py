import numpy as np, matplotlib.pyplot as plt
import pdd                                   # or: import pdd as triangle; triangle.triangulate(...)

t = np.linspace(0, 2 * np.pi, 48, endpoint=False)
ring = np.c_[np.arange(48), (np.arange(48) + 1) % 48]          # a closed loop of 48 segments
m = pdd.mesh(np.vstack([np.c_[np.cos(t), np.sin(t)], 0.4 * np.c_[np.cos(t), np.sin(t)]]),
             np.vstack([ring, ring + 48]), holes=[[0, 0]], max_area=0.004, subdomains=8)
v, tri = m["vertices"], m["triangles"]; plt.figure(figsize=(5, 4))
plt.tripcolor(v[:, 0], v[:, 1], tri, facecolors=m["triangle_markers"], cmap="tab10", alpha=0.5)
plt.triplot(v[:, 0], v[:, 1], tri, lw=0.3, color="k"); plt.gca().set_aspect("equal"); plt.axis("off")
plt.title(f"{len(tri)} triangles, {m['statistics']['subdomains']} subdomains, "
          f"min angle {m['statistics']['min_angle_deg']:.1f}°"); plt.savefig("annulus.png", dpi=72)
