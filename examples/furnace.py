# White furnace of a white metal with numpy and the dspbr module: the cosine-weighted mean of
# f cos / pdf over the hemisphere is the directional albedo, 1 for a lossless (energy-compensated)
# metal. Run: PYTHONPATH=build/python /usr/bin/python3 examples/furnace.py
import numpy as np
import dspbr

bsdf = dspbr.Bsdf({"metallic": 1, "albedo": [1, 1, 1], "roughness": 0.5})
u = np.random.default_rng(1).random((400_000, 2))
r, phi = np.sqrt(u[:, 0]), 2 * np.pi * u[:, 1]  # cosine-weighted directions l, pdf = cos / pi
l = np.stack([r * np.cos(phi), r * np.sin(phi), np.sqrt(1 - u[:, 0])], axis=1)
for theta in (0, 45, 80):
    v = [np.sin(np.radians(theta)), 0, np.cos(np.radians(theta))]
    albedo = (bsdf.eval(v, l) * np.pi).mean(axis=0)  # f cos / pdf = f pi
    print(f"view {theta:2d} deg: albedo {albedo.round(4)}")
    assert np.all(np.abs(albedo - 1) < 0.01), albedo
