#!/usr/bin/env python3
"""Writes PathLab's scenes (.obj, .mtl, .ecs) next to this script. Deterministic: running it
again gives the same files. Run: python3 models/generate_models.py

Conventions the renderer relies on: a triangle's front side is where its vertices run
counter-clockwise; enclosures (the Cornell box, the furnace spheres) face inward, objects face
outward; Ke is emitted from the front side only.
"""
import math
import os

HERE = os.path.dirname(os.path.abspath(__file__))

# Cornell box colours (Kd), close to the published reflectances averaged into RGB.
WHITE = (0.725, 0.71, 0.68)
RED = (0.63, 0.065, 0.05)
GREEN = (0.14, 0.45, 0.091)

# Coordinates of Embree's cornell_box.obj (Cornell's measurements, in millimetres).
FLOOR = [(552.8, 0.0, 0.0), (0.0, 0.0, 0.0), (0.0, 0.0, 559.2), (549.6, 0.0, 559.2)]
CEILING = [(556.0, 548.8, 0.0), (556.0, 548.8, 559.2), (0.0, 548.8, 559.2), (0.0, 548.8, 0.0)]
BACK = [(549.6, 0.0, 559.2), (0.0, 0.0, 559.2), (0.0, 548.8, 559.2), (556.0, 548.8, 559.2)]
GREEN_WALL = [(0.0, 0.0, 559.2), (0.0, 0.0, 0.0), (0.0, 548.8, 0.0), (0.0, 548.8, 559.2)]
RED_WALL = [(552.8, 0.0, 0.0), (549.6, 0.0, 559.2), (556.0, 548.8, 559.2), (556.0, 548.8, 0.0)]
BOX_CENTRE = (278.0, 274.4, 279.6)
TALL_BLOCK = ([(423.0, 247.0), (265.0, 296.0), (314.0, 456.0), (472.0, 406.0)], 330.0)
SHORT_BLOCK = ([(130.0, 65.0), (82.0, 225.0), (240.0, 272.0), (290.0, 114.0)], 165.0)
CAMERA = "-vp 278 273 -800\n-vi 278 273 0\n-vu 0 1 0\n-fov 37\n"


def sub(a, b):
    return tuple(x - y for x, y in zip(a, b))


def cross(a, b):
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def dot(a, b):
    return sum(x * y for x, y in zip(a, b))


def normal_of(a, b, c):
    return cross(sub(b, a), sub(c, a))


class Mesh:
    """Triangles grouped by material, with optional per-vertex normals."""

    def __init__(self):
        self.vertices = []
        self.normals = []
        self.groups = []  # (name, material, [faces]); a face is [(v, vn or None), ...]

    def vertex(self, p):
        self.vertices.append(tuple(float(x) for x in p))
        return len(self.vertices)

    def normal(self, n):
        self.normals.append(tuple(float(x) for x in n))
        return len(self.normals)

    def group(self, name, material):
        self.groups.append((name, material, []))
        return self.groups[-1][2]

    def polygon(self, faces, points, facing):
        """A planar convex polygon, turned so its front side faces toward `facing`(point)
        when `facing` is given as ('toward', p) or away from it as ('away', p)."""
        mode, p = facing
        n = normal_of(*points[:3])
        toward = dot(n, sub(p, points[0])) > 0
        if toward != (mode == "toward"):
            points = list(reversed(points))
        ids = [self.vertex(q) for q in points]
        for k in range(1, len(ids) - 1):  # a fan: the polygons here are convex
            faces.append([(ids[0], None), (ids[k], None), (ids[k + 1], None)])

    def sphere(self, faces, centre, radius, segments, rings, outward, smooth):
        """A UV sphere; triangles at the poles so none has zero area."""
        def point(ring, seg):
            theta = math.pi * ring / rings
            phi = 2 * math.pi * seg / segments
            return (math.sin(theta) * math.cos(phi), math.cos(theta), math.sin(theta) * math.sin(phi))

        ids = {}
        for ring in range(rings + 1):
            for seg in range(segments if 0 < ring < rings else 1):
                d = point(ring, seg)
                v = self.vertex(tuple(c + radius * x for c, x in zip(centre, d)))
                n = self.normal(d if outward else tuple(-x for x in d)) if smooth else None
                ids[(ring, seg)] = (v, n)

        def at(ring, seg):
            return ids[(ring, 0)] if ring in (0, rings) else ids[(ring, seg % segments)]

        for ring in range(rings):
            for seg in range(segments):
                a, b = at(ring, seg), at(ring, seg + 1)
                c, d = at(ring + 1, seg), at(ring + 1, seg + 1)
                tris = []
                if ring > 0:
                    tris.append([a, b, d])
                if ring < rings - 1:
                    tris.append([a, d, c])
                for tri in tris:
                    # Orient by geometry: front side away from (outward) or toward the centre.
                    p = [self.vertices[v - 1] for v, _ in tri]
                    away = dot(normal_of(*p), sub(p[0], centre)) > 0
                    faces.append(tri if away == outward else list(reversed(tri)))

    def write(self, path, mtllib):
        lines = ["# Written by generate_models.py; edit that script, not this file.",
                 f"mtllib {mtllib}"]
        lines += [f"v {x:.6g} {y:.6g} {z:.6g}" for x, y, z in self.vertices]
        lines += [f"vn {x:.6g} {y:.6g} {z:.6g}" for x, y, z in self.normals]
        triangles = 0
        for name, material, faces in self.groups:
            lines += [f"o {name}", f"usemtl {material}"]
            for face in faces:
                lines.append("f " + " ".join(f"{v}//{n}" if n else f"{v}" for v, n in face))
                triangles += 1
        with open(path, "w") as f:
            f.write("\n".join(lines) + "\n")
        return triangles


def write_mtl(path, materials):
    lines = ["# Written by generate_models.py; edit that script, not this file."]
    for name, keys in materials:
        lines.append(f"newmtl {name}")
        for key, value in keys:
            if isinstance(value, tuple):
                lines.append(f"{key} {value[0]:.6g} {value[1]:.6g} {value[2]:.6g}")
            else:
                lines.append(f"{key} {value:.6g}")
        for c in range(3):  # the loader warns otherwise
            total = sum(v[c] if isinstance(v, tuple) else 0 for k, v in keys if k in ("Kd", "Ks", "Kt"))
            assert total <= 1.0 + 1e-9, f"{name} is not energy conserving"
    with open(path, "w") as f:
        f.write("\n".join(lines) + "\n")


def write_ecs(path, comment, body):
    with open(path, "w") as f:
        f.write("# " + comment.replace("\n", "\n# ") + "\n" + body)


def check(mesh, name):
    """Every face index in range, no triangle without area."""
    for _, _, faces in mesh.groups:
        for face in faces:
            for v, n in face:
                assert 1 <= v <= len(mesh.vertices), name
                assert n is None or 1 <= n <= len(mesh.normals), name
            p = [mesh.vertices[v - 1] for v, _ in face]
            assert dot(normal_of(*p), normal_of(*p)) > 0, f"{name}: zero-area triangle"


def box_walls(mesh, floor_material):
    inside = ("toward", BOX_CENTRE)
    mesh.polygon(mesh.group("floor", floor_material), FLOOR, inside)
    mesh.polygon(mesh.group("ceiling", "white"), CEILING, inside)
    mesh.polygon(mesh.group("back_wall", "white"), BACK, inside)
    # Seen from Embree's camera (at z = -800 looking down +z), x = 552 is on the image's left.
    mesh.polygon(mesh.group("red_wall", "red"), RED_WALL, inside)
    mesh.polygon(mesh.group("green_wall", "green"), GREEN_WALL, inside)


def block(mesh, name, material, footprint_and_height):
    footprint, height = footprint_and_height
    faces = mesh.group(name, material)
    centre = (sum(x for x, _ in footprint) / 4, height / 2, sum(z for _, z in footprint) / 4)
    outside = ("away", centre)
    mesh.polygon(faces, [(x, height, z) for x, z in footprint], outside)
    for k in range(4):
        (x0, z0), (x1, z1) = footprint[k], footprint[(k + 1) % 4]
        mesh.polygon(faces, [(x0, 0, z0), (x1, 0, z1), (x1, height, z1), (x0, height, z0)], outside)


def cornell_box_vi2():
    mesh = Mesh()
    box_walls(mesh, "floor")
    block(mesh, "tall_block", "mirror", TALL_BLOCK)
    mesh.sphere(mesh.group("glass_sphere", "glass"), (186.0, 82.5, 169.0), 82.5, 48, 24,
                outward=True, smooth=True)
    # Just under the ceiling, facing down.
    light = [(343.0, 548.0, 227.0), (343.0, 548.0, 332.0), (213.0, 548.0, 332.0), (213.0, 548.0, 227.0)]
    mesh.polygon(mesh.group("light", "light"), light, ("toward", (278.0, 0.0, 279.5)))
    check(mesh, "VI2")
    n = mesh.write(os.path.join(HERE, "cornell_box_VI2_Specular.obj"), "cornell_box_VI2_Specular.mtl")
    write_mtl(os.path.join(HERE, "cornell_box_VI2_Specular.mtl"), [
        ("white", [("Kd", WHITE)]),
        ("red", [("Kd", RED)]),
        ("green", [("Kd", GREEN)]),
        # A little mirror in the floor, so the branching lab traces two rays there.
        ("floor", [("Kd", tuple(0.8 * c for c in WHITE)), ("Ks", (0.15, 0.15, 0.15))]),
        ("mirror", [("Ks", (0.9, 0.9, 0.9))]),
        ("glass", [("Ks", (0.1, 0.1, 0.1)), ("Kt", (0.9, 0.9, 0.9)), ("Ni", 1.5)]),
        ("light", [("Ke", (21.0, 18.0, 14.0))]),
    ])
    write_ecs(os.path.join(HERE, "cornell_box_VI2_Specular.ecs"),
              "The Cornell box with a mirror block, a glass sphere and an area light.\n"
              "Camera of Embree's cornell_box.ecs.",
              "-i cornell_box_VI2_Specular.obj\n" + CAMERA)
    return n


def cornell_box_diffuse():
    mesh = Mesh()
    box_walls(mesh, "white")
    block(mesh, "tall_block", "white", TALL_BLOCK)
    block(mesh, "short_block", "white", SHORT_BLOCK)
    check(mesh, "diffuse")
    n = mesh.write(os.path.join(HERE, "cornell_box_diffuse.obj"), "cornell_box_diffuse.mtl")
    write_mtl(os.path.join(HERE, "cornell_box_diffuse.mtl"), [
        ("white", [("Kd", WHITE)]), ("red", [("Kd", RED)]), ("green", [("Kd", GREEN)])])
    # The floor straight below the light, 540 mm away, reflects Kd/π·I/r² ≈ 0.72/π·I/291600 of
    # radiance directly: I = 150000 gives ≈ 0.12 there; with the walls nearer the light and the
    # interreflections the mean pixel value is about 0.3, far from clipping in a PNG.
    write_ecs(os.path.join(HERE, "cornell_box_diffuse.ecs"),
              "The diffuse Cornell box (both blocks), lit by one point light under the ceiling.",
              "-i cornell_box_diffuse.obj\n" + CAMERA + "-pointlight 278 540 279.5 150000 150000 150000\n")
    return n


def closed_sphere(name, wall, description, inner=None):
    """A closed sphere (radius 1, facing inward) of the material `wall` = (name, keys), the camera
    inside; optionally an `inner` sphere (radius 0.3, facing outward) of another material."""
    mesh = Mesh()
    mesh.sphere(mesh.group("enclosure", wall[0]), (0.0, 0.0, 0.0), 1.0, 64, 32, outward=False, smooth=False)
    materials = [wall]
    if inner:
        material, keys = inner
        mesh.sphere(mesh.group("inner_sphere", material), (0.0, 0.0, 0.0), 0.3, 32, 16,
                    outward=True, smooth=False)
        materials.append((material, keys))
        description += f"\nInside it a {material} sphere (radius 0.3), which changes nothing."
    check(mesh, name)
    n = mesh.write(os.path.join(HERE, name + ".obj"), name + ".mtl")
    write_mtl(os.path.join(HERE, name + ".mtl"), materials)
    write_ecs(os.path.join(HERE, name + ".ecs"), description,
              f"-i {name}.obj\n-vp 0 0 -0.7\n-vi 0 0 0\n-vu 0 1 0\n-fov 90\n")
    return n


def furnace(name, albedo, inner=None):
    """Diffuse walls of albedo a emitting Le = 1: the radiance is Le/(1-a) everywhere."""
    return closed_sphere(name, ("wall", [("Kd", (albedo,) * 3), ("Ke", (1.0, 1.0, 1.0))]),
                         f"Furnace: a closed sphere of diffuse albedo {albedo} emitting Le = 1; "
                         f"radiance everywhere 1/(1-a) = {1 / (1 - albedo):g}.", inner)


def mirror_furnace(reflectance):
    """Perfect-mirror walls (Ks = s, no Kd, no Kt) emitting Le = 1. Every path meets only mirror
    reflections and next-event estimation finds nothing (no Kd), so the light is counted only
    through the emission seen after specular bounces: a lab that leaves it out gives exactly Le."""
    s = reflectance
    return closed_sphere("mirror_furnace", ("wall", [("Ks", (s,) * 3), ("Ke", (1.0, 1.0, 1.0))]),
                         f"Mirror furnace: a closed sphere of perfect mirror walls (Ks = s = {s:g}, "
                         f"no Kd, no Kt) emitting Le = 1;\n"
                         f"radiance everywhere 1/(1-s) = {1 / (1 - s):g}; with a depth limit D, "
                         f"(1-s^(D+1))/(1-s); without emission after specular bounces, 1.")


def refraction_check():
    """A glass sphere before a wall whose left half glows red and right half green: refraction
    turns the view through the sphere upside down and left-right, so a lab that sends the
    transmitted ray on unbent (or loses it) shows the wrong colours there."""
    mesh = Mesh()
    front = ("toward", (0.0, 0.0, -3.0))
    mesh.polygon(mesh.group("red_half", "red_glow"), [(-4.0, -4.0, 2.0), (0.0, -4.0, 2.0), (0.0, 4.0, 2.0), (-4.0, 4.0, 2.0)], front)
    mesh.polygon(mesh.group("green_half", "green_glow"), [(0.0, -4.0, 2.0), (4.0, -4.0, 2.0), (4.0, 4.0, 2.0), (0.0, 4.0, 2.0)], front)
    mesh.sphere(mesh.group("glass_sphere", "glass"), (0.0, 0.0, 0.0), 0.8, 48, 24, outward=True, smooth=True)
    check(mesh, "refraction_check")
    n = mesh.write(os.path.join(HERE, "refraction_check.obj"), "refraction_check.mtl")
    write_mtl(os.path.join(HERE, "refraction_check.mtl"), [
        ("red_glow", [("Ke", (1.0, 0.2, 0.2))]),
        ("green_glow", [("Ke", (0.2, 1.0, 0.2))]),
        ("glass", [("Kt", (1.0, 1.0, 1.0)), ("Ni", 1.5)]),
    ])
    write_ecs(os.path.join(HERE, "refraction_check.ecs"),
              "A glass sphere before a red|green glowing wall: the grader's check of refraction.",
              "-i refraction_check.obj\n-vp 0 0 -3\n-vi 0 0 0\n-vu 0 1 0\n-fov 40\n")
    return n


# mixed_surfaces' two-component materials. Pick probability of the diffuse component by
# strength = reduceMax | channel sum or average | luminance (Rec. 709):
#   glossy (red Kd + teal Ks):      0.64 | 0.535 | 0.41
#   translucent (red Kd + cyan Kt): 0.615 | 0.505 | 0.44
GLOSSY_KD, GLOSSY_KS = (0.8, 0.1, 0.02), (0.05, 0.45, 0.3)
TRANSLUCENT_KD, TRANSLUCENT_KT = (0.8, 0.2, 0.02), (0.05, 0.5, 0.45)


def diffuse_pick_probabilities(kd, other):
    """The diffuse component's pick probability beside `other` by each strength: reduceMax,
    channel sum (the average gives the same), luminance."""
    strengths = (max, sum, lambda k: 0.2126 * k[0] + 0.7152 * k[1] + 0.0722 * k[2])
    return [s(kd) / (s(kd) + s(other)) for s in strengths]


def check_colours_tell_strengths_apart(name, kd, other):
    """A lab that picks by one strength and divides by another's probability is off by their
    ratio: at least 8% apart, so the grader sees it."""
    p = diffuse_pick_probabilities(kd, other)
    for i in range(3):
        for j in range(i):
            assert abs(p[i] / p[j] - 1) > 0.08, f"{name}: strengths give alike probabilities {p}"
    # Each channel's reflectance mostly from one component: red diffuse, green and blue not.
    assert kd[0] > 4 * other[0] and other[1] > 2 * kd[1] and other[2] > 2 * kd[2], name


def mixed_surfaces():
    """A room whose surfaces mix a diffuse component with a mirror (Kd+Ks) or a transparent one
    (Kd+Kt), lit by one lamp that faces one wall: what a diffuse bounce brings back depends
    strongly on its direction, so a lab that draws diffuse directions from part of the hemisphere
    only (a random number reused from the component pick, one number for both coordinates, the
    wrong side of a surface hit from behind) gets the wrong mean, which the furnaces, alike in
    every direction, cannot show.

    The two components differ in colour: a red diffuse one beside a teal mirror or a cyan glass
    whose greens and blues are strong. Their strengths by the largest channel (reduceMax), the
    channel sum or average, and the luminance give clearly different pick probabilities (see
    GLOSSY_KD), and each channel's light comes mostly from one component: a lab that picks
    with one strength and divides by another's probability makes the red channel too dark and
    the blue too bright, or the reverse, which no grey material could show."""
    mesh = Mesh()
    # A box x in [-1, 1], y in [0, 2], z in [0, 2], open at z = 0 where the camera looks in, so
    # light arrives from the back more than from the front. Seen from the camera (at z < 0
    # looking down +z), x = -1 is on the image's right.
    inside = ("toward", (0.0, 1.0, 1.0))
    mesh.polygon(mesh.group("floor", "glossy"), [(-1, 0, 0), (1, 0, 0), (1, 0, 2), (-1, 0, 2)], inside)
    mesh.polygon(mesh.group("ceiling", "glossy"), [(-1, 2, 0), (1, 2, 0), (1, 2, 2), (-1, 2, 2)], inside)
    mesh.polygon(mesh.group("back_wall", "glossy"), [(-1, 0, 2), (1, 0, 2), (1, 2, 2), (-1, 2, 2)], inside)
    mesh.polygon(mesh.group("bright_wall", "bright"), [(-1, 0, 0), (-1, 0, 2), (-1, 2, 2), (-1, 2, 0)], inside)
    mesh.polygon(mesh.group("dark_wall", "dark"), [(1, 0, 0), (1, 0, 2), (1, 2, 2), (1, 2, 0)], inside)
    # The lamp, a panel hanging under the ceiling, shines on the bright wall only: everything else
    # is lit by what that wall sends back. Its back, seen from the camera, is a grey diffuse panel.
    lamp = [(-0.3, 1.3, 0.3), (-0.3, 1.3, 1.7), (-0.3, 1.9, 1.7), (-0.3, 1.9, 0.3)]
    mesh.polygon(mesh.group("lamp", "lamp"), lamp, ("toward", (-1.0, 1.6, 1.0)))
    # Two spheres with smooth normals (so the diffuse bounce's frame turns over them): a large
    # Kd+Kt one, inside which paths meet the surface from behind, and a Kd+Ks one.
    spheres = [("translucent_sphere", "translucent", (-0.3, 0.62, 1.1), 0.6),
               ("glossy_sphere", "glossy", (0.6, 0.39, 1.55), 0.38)]
    (_, _, c0, r0), (_, _, c1, r1) = spheres
    assert dot(sub(c0, c1), sub(c0, c1)) > (r0 + r1) ** 2, "the spheres intersect"
    for name, material, centre, radius in spheres:
        mesh.sphere(mesh.group(name, material), centre, radius, 16, 8, outward=True, smooth=True)
    check(mesh, "mixed_surfaces")
    check_colours_tell_strengths_apart("glossy", GLOSSY_KD, GLOSSY_KS)
    check_colours_tell_strengths_apart("translucent", TRANSLUCENT_KD, TRANSLUCENT_KT)
    n = mesh.write(os.path.join(HERE, "mixed_surfaces.obj"), "mixed_surfaces.mtl")
    write_mtl(os.path.join(HERE, "mixed_surfaces.mtl"), [
        ("glossy", [("Kd", GLOSSY_KD), ("Ks", GLOSSY_KS)]),
        ("translucent", [("Kd", TRANSLUCENT_KD), ("Kt", TRANSLUCENT_KT), ("Ni", 1.5)]),
        ("bright", [("Kd", (0.8, 0.8, 0.8))]),
        ("dark", [("Kd", (0.25, 0.25, 0.25))]),
        ("lamp", [("Kd", (0.5, 0.5, 0.5)), ("Ke", (6.0, 6.0, 6.0))]),
    ])
    write_ecs(os.path.join(HERE, "mixed_surfaces.ecs"),
              "Kd+Ks and Kd+Kt surfaces lit by a lamp that faces one wall: the grader's check that\n"
              "diffuse directions cover the whole hemisphere.",
              "-i mixed_surfaces.obj\n-vp 0 1 -2.4\n-vi 0 1 1\n-vu 0 1 0\n-fov 45\n")
    return n


# The glossy plates of Veach's multiple importance sampling figure (Veach 1997, fig. 9.2): Phong
# exponents from rough to sharp, nearest the camera first, and lights from small to large, left
# to right, each of the same power.
PLATE_EXPONENTS = [12, 60, 300, 1500]
PLATE_KS = (0.7, 0.7, 0.7)
LIGHT_RADII = [0.05, 0.15, 0.4, 1.0]
LIGHT_POWER = 0.5  # Ke times the sphere's squared radius: the same power for every light


def normalized(v):
    length = math.sqrt(dot(v, v))
    return tuple(x / length for x in v)


def veach_plates():
    """Four glossy plates (Phong lobes of exponent PLATE_EXPONENTS, Ks 0.7, MTL illum 2 with Ns)
    each turned so that the camera sees the row of four sphere lights reflected in it, before a
    dark diffuse wall and over a diffuse floor. Sampling the lobe alone is noisy where a rough
    plate reflects a small light, sampling the lights alone where a sharp plate reflects a large
    one: lab 5's scene, and lab 6's, whose noise check compares the two strategies on it."""
    mesh = Mesh()
    camera = (0.0, 2.0, 9.0)
    lights_centre = (0.0, 4.2, -2.5)
    for k, exponent in enumerate(PLATE_EXPONENTS):
        centre = (0.0, 0.3 + 0.55 * k, 2.4 - 1.1 * k)
        to_camera = normalized(sub(camera, centre))
        to_lights = normalized(sub(lights_centre, centre))
        n = normalized(tuple(a + b for a, b in zip(to_camera, to_lights)))
        across = (1.0, 0.0, 0.0)
        along = normalized(cross(n, across))  # in the plate, away from or toward the camera
        half_width, half_depth = 3.6, 0.42
        corners = [tuple(c + sx * half_width * a + sy * half_depth * b
                         for c, a, b in zip(centre, across, along))
                   for sx, sy in ((-1, -1), (1, -1), (1, 1), (-1, 1))]
        mesh.polygon(mesh.group(f"plate_{k + 1}", f"plate_{k + 1}"), corners,
                     ("toward", tuple(c + x for c, x in zip(centre, n))))
    for k, radius in enumerate(LIGHT_RADII):
        centre = (-3.0 + 2.0 * k, lights_centre[1], lights_centre[2])
        mesh.sphere(mesh.group(f"light_{k + 1}", f"light_{k + 1}"), centre, radius, 16, 8,
                    outward=True, smooth=False)
    mesh.polygon(mesh.group("wall", "wall"), [(-8, -1, -5), (8, -1, -5), (8, 8, -5), (-8, 8, -5)],
                 ("toward", (0.0, 0.0, 0.0)))
    mesh.polygon(mesh.group("floor", "floor"), [(-8, -0.5, -5), (8, -0.5, -5), (8, -0.5, 12), (-8, -0.5, 12)],
                 ("toward", (0.0, 1.0, 0.0)))
    check(mesh, "veach_plates")
    n = mesh.write(os.path.join(HERE, "veach_plates.obj"), "veach_plates.mtl")
    materials = [(f"plate_{k + 1}", [("Ks", PLATE_KS), ("Ns", float(e)), ("illum", 2.0)])
                 for k, e in enumerate(PLATE_EXPONENTS)]
    materials += [(f"light_{k + 1}", [("Ke", (LIGHT_POWER / r ** 2,) * 3)])
                  for k, r in enumerate(LIGHT_RADII)]
    materials += [("wall", [("Kd", (0.1, 0.1, 0.1))]), ("floor", [("Kd", (0.3, 0.3, 0.3))])]
    write_mtl(os.path.join(HERE, "veach_plates.mtl"), materials)
    write_ecs(os.path.join(HERE, "veach_plates.ecs"),
              "Veach's glossy plates (rough to sharp) lit by four lights (small to large) of one\n"
              "power: lab 5 (lobe sampling alone), lab 6 (both strategies, or one: --strategy).",
              "-i veach_plates.obj\n-vp 0 2 9\n-vi 0 1.4 0\n-vu 0 1 0\n-fov 40\n")
    return n


GLOSSY_FURNACE_KS = 0.8
GLOSSY_FURNACE_EXPONENT = 12
GLOSSY_FURNACE_TILT = 60  # degrees from the plate's normal, glossy_furnace_tilted's view


def glossy_furnace():
    """A glossy plate (Ks k, a Phong lobe of exponent n) seen inside a closed sphere that emits
    Le = 1 and reflects nothing, in two views. Head-on (glossy_furnace) the plate's lobe lies
    about its normal and reflects exactly k of the light arriving from all around (the (n + 2)/(2π)
    of the modified Phong BRDF: handout 05), so its radiance is k·Le; the camera's field of view
    is 1 degree, where the lobe's tilt loses less than 1e-4 of it past the horizon. Seen at
    GLOSSY_FURNACE_TILT degrees (glossy_furnace_tilted, the same mesh), the lobe leans toward the
    horizon and reflects k·Le·ρ(β), ρ the lobe's integral of cos θ above the surface (about 0.503
    at 60 degrees and n = 12; the grader integrates it), where a mirror would still show k·Le: the
    view tells a glossy bounce from a mirror one. Its field of view is 0.05 degrees, across which
    ρ changes by less than 0.1%. Lab 5's analytic checks of the glossy bounce."""
    mesh = Mesh()
    mesh.sphere(mesh.group("enclosure", "glow"), (0.0, 0.0, 0.0), 1.0, 64, 32, outward=False, smooth=False)
    mesh.polygon(mesh.group("plate", "plate"), [(-0.4, -0.4, 0), (0.4, -0.4, 0), (0.4, 0.4, 0), (-0.4, 0.4, 0)],
                 ("toward", (0.0, 0.0, -1.0)))
    check(mesh, "glossy_furnace")
    n = mesh.write(os.path.join(HERE, "glossy_furnace.obj"), "glossy_furnace.mtl")
    k, e = GLOSSY_FURNACE_KS, GLOSSY_FURNACE_EXPONENT
    write_mtl(os.path.join(HERE, "glossy_furnace.mtl"), [
        ("glow", [("Ke", (1.0, 1.0, 1.0))]),
        ("plate", [("Ks", (k, k, k)), ("Ns", float(e)), ("illum", 2.0)]),
    ])
    write_ecs(os.path.join(HERE, "glossy_furnace.ecs"),
              f"Glossy furnace: a glossy plate (Ks {k:g}, Phong exponent {e}) seen head-on inside a sphere\n"
              f"that emits Le = 1 and reflects nothing: its radiance is Ks·Le = {k:g}.",
              "-i glossy_furnace.obj\n-vp 0 0 -0.8\n-vi 0 0 0\n-vu 0 1 0\n-fov 1\n")
    tilt = math.radians(GLOSSY_FURNACE_TILT)
    at = (0.0, 0.8 * math.sin(tilt), -0.8 * math.cos(tilt))
    write_ecs(os.path.join(HERE, "glossy_furnace_tilted.ecs"),
              f"The glossy furnace's plate seen at {GLOSSY_FURNACE_TILT} degrees from its normal: its lobe leans\n"
              f"toward the horizon and reflects Ks·Le·rho, rho about 0.503 (a mirror would show Ks·Le).",
              f"-i glossy_furnace.obj\n-vp {at[0]:.6g} {at[1]:.6g} {at[2]:.6g}\n-vi 0 0 0\n-vu 0 1 0\n-fov 0.05\n")
    return n


def main():
    counts = {
        "cornell_box_VI2_Specular": cornell_box_vi2(),
        "cornell_box_diffuse": cornell_box_diffuse(),
        "furnace": furnace("furnace", 0.5),
        "furnace_a08": furnace("furnace_a08", 0.8),
        "furnace_mirror": furnace("furnace_mirror", 0.5, ("mirror", [("Ks", (1.0, 1.0, 1.0))])),
        "refraction_check": refraction_check(),
        "furnace_glass": furnace("furnace_glass", 0.5, ("glass", [("Kt", (1.0, 1.0, 1.0)), ("Ni", 1.5)])),
        "mirror_furnace": mirror_furnace(0.5),
        "mixed_surfaces": mixed_surfaces(),
        "veach_plates": veach_plates(),
        "glossy_furnace": glossy_furnace(),
    }
    for name, triangles in counts.items():
        print(f"{name}: {triangles} triangles")


if __name__ == "__main__":
    main()
