#!/usr/bin/env python3
"""Glint scene (YAML, SPEC sections 2, 3, 3b, 3c, 4) -> Mitsuba 3 scene dict, and a renderer that writes
Glint's conventions (a PFM: little-endian, rows bottom to top; +x on the image's right).

An independent check of Glint's path integrator: the physically based equivalent of a Glint scene,
rendered by Mitsuba 3's `path` integrator (see src/test/resources/reference-pt/README.md).

Equivalents:
- camera: Mitsuba `perspective` (or `thinlens` with aperture_radius = aperture, focus_distance = focus),
  fov on the x axis (Glint's fov is horizontal), same look_at and up. Mitsuba's camera frame puts its
  local +x (cross(up, dir)) on the image's LEFT; Glint puts it on the right (POV-Ray's left-handed
  convention), so the rendered image is mirrored horizontally before it is written.
- box pixel filter; the image is the plain average of the samples (SPEC section 3).
- background -> `constant` environment emitter (seen by every escaping ray, so a sky lights the scene).
- matte -> `diffuse` (albedo = color); planes are two-sided in Glint, so every plane's BSDF is wrapped
  in `twosided`. A plane becomes square rings of rectangles about the point nearest the camera, small
  near it (single precision) and out to PLANE_HALF (so that its horizon is where Glint's is).
- metal of roughness 0 (alpha below 0.001, where Glint's metal is a mirror) -> `glint_mirror`, a
  Python plugin defined here: a perfect mirror weighted by Schlick's Fresnel with F0 = color, exactly
  SPEC section 4's. (Mitsuba's `conductor` has the complex-index Fresnel instead, and `principled`
  at roughness 0 is GGX of alpha 0.001, whose lobe, evaluated for a point or directional light,
  makes fireflies.)
- rough metal -> `principled` with metallic 1, base_color = color, roughness = roughness: its metallic lobe is
  GGX with alpha = roughness^2 (at least 0.001) and Schlick's Fresnel with F0 = base_color at the
  microfacet normal, as SPEC section 4's metal. Its masking is Smith's separable G1 G1, not the
  height-correlated one (a small difference for rough metal; none for a mirror, where alpha is 0.001).
- glass -> `dielectric` (roughness 0) or `roughdielectric` (GGX, alpha = roughness^2, visible-normal
  sampling; separable masking again), int_ior = ior, ext_ior = 1, specular_transmittance = color.
  Mitsuba scales radiance by 1/eta^2 on refraction; on a closed ball entered and left, it cancels.
- point light, radius 0 -> `point` of intensity color x intensity (radiant intensity, 1/d^2).
- point light with radius r -> a sphere with an `area` emitter of radiance color x intensity / (pi r^2)
  and a black diffuse surface.
- directional light, angle 0 -> `directional` of irradiance color x intensity, direction of travel.
- directional light with angle a -> a sphere far away (D = SUN_DISTANCE from the scene's centre,
  towards -direction: far enough that the far floor too sees it at the same angle) of radius
  D sin(a/2), so that it subtends exactly the apparent diameter a, with an `area` emitter of radiance
  color x intensity / (pi sin^2(a/2)) (+ the background, which Glint adds to the disc and which the
  sphere would otherwise hide).
- `ambient` plays no part (SPEC 3b); `views` and `render` are not read (the scene's camera is rendered).
- samples: Mitsuba's `stratified` sampler, in passes of --pass-spp samples with seeds of their own,
  averaged (a high-spp image does not fit in memory in one pass).

Checked against the shipped references (/work/shared/reference-pt, made by another hand with the same
renderer): a 256-spp render of each by this converter (seeds 1 and 2) has the relMSE and 8-bit error
those references' bounds imply for the other renderer's own 256-spp runs (bound / 1.5, or / 2), within
a few per cent, mirrored and orientated right.

Usage:
  glint2mitsuba.py SCENE.yaml OUT.pfm --width 200 --height 150 --spp 4096 [--seed S] [--depth 64]
                   [--pass-spp 256] [--variant llvm_ad_rgb]
--depth is Glint's recursion_max (surface hits); Mitsuba's max_depth is that + 1 (Mitsuba counts the
camera ray's own emitter hit as depth 1).
"""
import argparse
import math
import os
import sys

import numpy as np
import yaml

PLANE_NEAR = 50.0
PLANE_GROWTH = 10.0
PLANE_HALF = 5.0e5
SUN_DISTANCE = 1.0e7

PRESETS = {
    "matte": {"type": "matte", "color": [0.8, 0.8, 0.8]},
    "metal": {"type": "metal", "color": [0.9, 0.9, 0.9], "roughness": 0.0},
    "glass": {"type": "glass", "color": [1.0, 1.0, 1.0], "ior": 1.5, "roughness": 0.0},
}
TYPE_DEFAULTS = {
    "matte": {"color": [0.8, 0.8, 0.8]},
    "metal": {"color": [0.9, 0.9, 0.9], "roughness": 0.0},
    "glass": {"color": [1.0, 1.0, 1.0], "ior": 1.5, "roughness": 0.0},
}


def vec(v, default=None):
    if v is None:
        return None if default is None else np.array(default, dtype=float)
    return np.array([float(x) for x in v], dtype=float)


def normalize(v):
    return v / np.linalg.norm(v)


def resolve_material(spec, named):
    if spec is None:
        spec = "matte"
    if isinstance(spec, str):
        if spec in named:
            return resolve_material(named[spec], {})
        if spec in PRESETS:
            return dict(PRESETS[spec])
        raise ValueError("unknown material " + spec)
    t = spec["type"]
    m = dict(TYPE_DEFAULTS[t])
    m.update(spec)
    return m


def rgb(c):
    return {"type": "rgb", "value": [float(x) for x in c]}


def register_schlick_mirror():
    """A Mitsuba BSDF (Python plugin `glint_mirror`): Glint's metal at roughness 0, a perfect mirror whose
    reflection is weighted by Schlick's Fresnel F0 + (1 - F0)(1 - cos)^5 with F0 = color, on either side."""
    import drjit as dr
    import mitsuba as mi

    class SchlickMirror(mi.BSDF):
        def __init__(self, props):
            mi.BSDF.__init__(self, props)
            self.f0 = mi.Color3f(props["r"], props["g"], props["b"])
            flags = mi.BSDFFlags.DeltaReflection | mi.BSDFFlags.FrontSide | mi.BSDFFlags.BackSide
            self.m_components = [flags]
            self.m_flags = flags

        def sample(self, ctx, si, sample1, sample2, active):
            cos = dr.abs(mi.Frame3f.cos_theta(si.wi))
            bs = mi.BSDFSample3f()
            bs.wo = mi.reflect(si.wi)
            bs.pdf = mi.Float(1.0)
            bs.eta = mi.Float(1.0)
            bs.sampled_type = mi.UInt32(+mi.BSDFFlags.DeltaReflection)
            bs.sampled_component = mi.UInt32(0)
            m = 1.0 - cos
            m2 = m * m
            value = self.f0 + (1.0 - self.f0) * (m2 * m2 * m)
            active = active & (cos > 0)
            return (bs, dr.select(active, value, mi.Color3f(0.0)))

        def eval(self, ctx, si, wo, active):
            return mi.Color3f(0.0)

        def pdf(self, ctx, si, wo, active):
            return mi.Float(0.0)

        def eval_pdf(self, ctx, si, wo, active):
            return mi.Color3f(0.0), mi.Float(0.0)

        def traverse(self, callback):
            pass

        def parameters_changed(self, keys):
            pass

        def to_string(self):
            return "SchlickMirror[]"

    mi.register_bsdf("glint_mirror", lambda props: SchlickMirror(props))


def bsdf_of(m):
    t = m["type"]
    if t == "matte":
        return {"type": "diffuse", "reflectance": rgb(m["color"])}
    if t == "metal" and float(m.get("roughness", 0.0)) ** 2 < 0.001:
        c = [float(x) for x in m["color"]]
        return {"type": "glint_mirror", "r": c[0], "g": c[1], "b": c[2]}
    if t == "metal":
        return {"type": "principled", "base_color": rgb(m["color"]), "metallic": 1.0,
                "roughness": float(m.get("roughness", 0.0))}
    if t == "glass":
        r = float(m.get("roughness", 0.0))
        b = {"int_ior": float(m.get("ior", 1.5)), "ext_ior": 1.0,
             "specular_transmittance": rgb(m.get("color", [1, 1, 1]))}
        if r > 0 and r * r >= 0.001:
            b.update({"type": "roughdielectric", "distribution": "ggx", "alpha": r * r, "sample_visible": True})
        else:
            b["type"] = "dielectric"
        return b
    raise ValueError("unknown material type " + t)


def plane_rectangles(p, n, eye):
    """Glint's infinite plane through p with unit normal n as rectangles (Mitsuba has no infinite plane):
    a square of half-size PLANE_NEAR about the point of the plane nearest the eye, then square rings each
    PLANE_GROWTH times wider, out to PLANE_HALF. Each rectangle's size sets how precisely Mitsuba (in
    single precision) finds a point on it, so the plane near the eye is made of small ones."""
    import mitsuba as mi
    T = mi.ScalarTransform4f
    c = eye - np.dot(eye - p, n) * n
    helper = np.array([0, 1.0, 0]) if abs(n[1]) < 0.9 else np.array([1.0, 0, 0])
    frame = T().look_at(origin=c.tolist(), target=(c + n).tolist(), up=helper.tolist())

    def rect(x0, x1, y0, y1):
        return frame @ T().translate([(x0 + x1) / 2, (y0 + y1) / 2, 0]) @ T().scale([(x1 - x0) / 2, (y1 - y0) / 2, 1])

    a = PLANE_NEAR
    out = [rect(-a, a, -a, a)]
    while a < PLANE_HALF:
        b = a * PLANE_GROWTH
        out += [rect(-b, b, a, b), rect(-b, b, -b, -a), rect(-b, -a, -a, a), rect(a, b, -a, a)]
        a = b
    return out


def convert(scene, width, height, spp, depth, seed=0, sampler="stratified", samples_per_pass=None):
    """The Mitsuba scene dict of a parsed Glint scene; returns (dict, needs_mirror)."""
    import mitsuba as mi
    T = mi.ScalarTransform4f
    cam = scene.get("camera") or {}
    pos = vec(cam.get("position"), [0, 1, -5])
    look = vec(cam.get("look_at")) if cam.get("look_at") is not None else pos + np.array([0, 0, 1.0])
    up = vec(cam.get("up"), [0, 1, 0])
    fov = float(cam.get("fov", 60))
    aperture = float(cam.get("aperture", 0.0))
    focus = float(cam.get("focus", np.linalg.norm(look - pos)))
    sensor = {
        "type": "perspective",
        "fov": fov,
        "fov_axis": "x",
        "to_world": T().look_at(origin=pos.tolist(), target=look.tolist(), up=up.tolist()),
        "film": {"type": "hdrfilm", "width": width, "height": height, "rfilter": {"type": "box"},
                 "pixel_format": "rgb", "component_format": "float32"},
        "sampler": {"type": sampler, "sample_count": spp, "seed": seed},
        "near_clip": 1e-3,
        "far_clip": 1e9,
    }
    if aperture > 0:
        sensor["type"] = "thinlens"
        sensor["aperture_radius"] = aperture
        sensor["focus_distance"] = focus
    integrator = {"type": "path", "max_depth": depth + 1, "hide_emitters": False}
    if samples_per_pass:
        integrator["samples_per_pass"] = samples_per_pass
    d = {"type": "scene", "integrator": integrator, "sensor": sensor}

    background = vec(scene.get("background"), [0, 0, 0])
    if np.any(background > 0):
        d["background"] = {"type": "constant", "radiance": rgb(background)}

    named = scene.get("materials") or {}
    centres = []
    for i, o in enumerate(scene.get("objects") or []):
        m = resolve_material(o.get("material"), named)
        b = bsdf_of(m)
        if o["type"] == "sphere":
            c = vec(o["center"])
            centres.append(c)
            d["obj%d" % i] = {"type": "sphere", "center": c.tolist(), "radius": float(o["radius"]), "bsdf": b}
        elif o["type"] == "plane":
            p = vec(o["point"])
            n = normalize(vec(o["normal"]))
            centres.append(p)
            if m["type"] != "glass":
                b = {"type": "twosided", "bsdf": b}
            for k, rect in enumerate(plane_rectangles(p, n, pos)):
                d["obj%d_%d" % (i, k)] = {"type": "rectangle", "to_world": rect, "bsdf": b}
        else:
            raise ValueError("unknown object type " + o["type"])
    centre = np.mean(centres, axis=0) if centres else look
    centre = np.array([centre[0], 0.0, centre[2]]) if centres else centre

    for i, l in enumerate(scene.get("lights") or []):
        color = vec(l.get("color"), [1, 1, 1])
        intensity = float(l.get("intensity", 1.0))
        power = color * intensity
        if l["type"] == "point":
            p = vec(l["position"])
            r = float(l.get("radius", 0.0))
            if r > 0:
                d["light%d" % i] = {"type": "sphere", "center": p.tolist(), "radius": r,
                                    "bsdf": {"type": "diffuse", "reflectance": rgb([0, 0, 0])},
                                    "emitter": {"type": "area", "radiance": rgb(power / (math.pi * r * r))}}
            else:
                d["light%d" % i] = {"type": "point", "position": p.tolist(), "intensity": rgb(power)}
        elif l["type"] == "directional":
            w = normalize(vec(l["direction"]))
            angle = float(l.get("angle", 0.0))
            if angle > 0:
                half = math.radians(angle) / 2
                s = math.sin(half)
                radiance = power / (math.pi * s * s) + background
                c = centre - w * SUN_DISTANCE
                d["light%d" % i] = {"type": "sphere", "center": c.tolist(), "radius": SUN_DISTANCE * s,
                                    "bsdf": {"type": "diffuse", "reflectance": rgb([0, 0, 0])},
                                    "emitter": {"type": "area", "radiance": rgb(radiance)}}
            else:
                d["light%d" % i] = {"type": "directional", "direction": w.tolist(), "irradiance": rgb(power)}
        else:
            raise ValueError("unknown light type " + l["type"])
    return d


def write_pfm(path, img):
    """img: H x W x 3, rows top to bottom, already in Glint's orientation."""
    h, w, _ = img.shape
    with open(path, "wb") as f:
        f.write(b"PF\n%d %d\n-1.0\n" % (w, h))
        f.write(np.ascontiguousarray(img[::-1].astype("<f4")).tobytes())


def read_pfm(path):
    with open(path, "rb") as f:
        data = f.read()
    parts = data.split(b"\n", 3)
    w, h = (int(x) for x in parts[1].split())
    scale = float(parts[2])
    arr = np.frombuffer(parts[3], dtype="<f4" if scale < 0 else ">f4", count=w * h * 3).reshape(h, w, 3)
    return arr[::-1].astype(np.float64)


def render(scene_path, width, height, spp, depth=64, seed=0, variant="llvm_ad_rgb", pass_spp=256,
           sampler="stratified"):
    """Renders the scene as Glint would show it: H x W x 3, rows top to bottom, float64."""
    import mitsuba as mi
    mi.set_variant(variant)
    register_schlick_mirror()
    with open(scene_path) as f:
        scene = yaml.safe_load(f)
    passes = max(1, spp // pass_spp) if spp > pass_spp else 1
    per_pass = spp // passes
    acc = None
    for k in range(passes):
        d = convert(scene, width, height, per_pass, depth, seed=seed * 100003 + k, sampler=sampler)
        img = np.array(mi.render(mi.load_dict(d), seed=seed * 100003 + k, spp=per_pass), dtype=np.float64)
        acc = img if acc is None else acc + img
    img = acc / passes
    return img[:, ::-1, :]  # Mitsuba's local +x is on the image's left; Glint's on its right


def main(argv):
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("scene")
    ap.add_argument("output")
    ap.add_argument("--width", type=int, default=200)
    ap.add_argument("--height", type=int, default=150)
    ap.add_argument("--spp", type=int, default=256)
    ap.add_argument("--depth", type=int, default=64, help="Glint's recursion_max (Mitsuba max_depth = this + 1)")
    ap.add_argument("--seed", type=int, default=0)
    ap.add_argument("--pass-spp", type=int, default=256, help="samples per pass; passes are averaged")
    ap.add_argument("--variant", default=os.environ.get("MI_VARIANT", "llvm_ad_rgb"))
    a = ap.parse_args(argv)
    img = render(a.scene, a.width, a.height, a.spp, a.depth, a.seed, a.variant, a.pass_spp)
    write_pfm(a.output, img)


if __name__ == "__main__":
    main(sys.argv[1:])
