#!/usr/bin/env python3
"""Assembles the fuzzers' seed corpora and the scene dictionary.

usage: tests/fuzz/make_corpus.py OUT_DIR

OUT_DIR/scene/   every scene in scenes/, every include in include/, every
                 scene string of the parser tests (raw strings and the
                 malformed-scene table), and tests/fuzz/regressions/*.pov
OUT_DIR/obj/     every OBJ in scenes/ (with its MTL appended after "#MTL",
                 the layout fuzz_obj.cc expects), small hand-made OBJ cases,
                 and tests/fuzz/regressions/*.obj
OUT_DIR/shapes/  one seed per shape kind fuzz_shapes.cc builds (its first
                 byte), each followed by a fixed stream of parameter bytes,
                 and tests/fuzz/regressions/*.shapes
OUT_DIR/patterns/  the pattern reference scenes (tests/reference/pov/
                 patterns_*.pov, normals.pov), small scenes built from
                 pattern_snippets() (every pattern and block pattern as a
                 pigment and a normal, every modifier and warp with
                 ordinary and extreme values, the maps in their forms,
                 layered textures), and tests/fuzz/regressions/*.patterns
OUT_DIR/scene.dict  the grammar's keywords and punctuation, for -dict=
"""
import ast
import hashlib
import pathlib
import re
import sys

ROOT = pathlib.Path(__file__).resolve().parents[2]


def save(folder: pathlib.Path, data: bytes) -> None:
    folder.mkdir(parents=True, exist_ok=True)
    (folder / hashlib.sha1(data).hexdigest()).write_bytes(data)


def c_string(body: str) -> bytes:
    """A C string literal's body as bytes (\\xE9 stays one byte)."""
    return ast.literal_eval('"' + body + '"').encode("latin-1", errors="replace")


def test_scenes(source: str):
    # R"( ... )" raw strings, as parse_ok / parse_error take them.
    for match in re.finditer(r'R"\((.*?)\)"', source, re.S):
        yield match.group(1).encode()
    # {"Name", "scene text", ...} rows of the malformed-scene tables.
    for match in re.finditer(r'\{"\w+",\s*((?:"(?:[^"\\]|\\.)*"\s*)+),', source):
        parts = re.findall(r'"((?:[^"\\]|\\.)*)"', match.group(1))
        try:
            yield b"".join(c_string(p) for p in parts)
        except (ValueError, SyntaxError):
            pass


OBJ_CASES = [
    b"v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n",
    b"v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nvt 0 0\nvt 1 0\nvt 0 1\nvn 0 0 1\nf 1/1/1 2/2/1 3/3/1 4/1/1\n",
    b"v 0 0 0\nv 1 0 0\nv 0 1 0\nf -3 -2 -1\n",
    b"v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 7\nf 0 1 2\n",
    b"v nan 0 0\nv 1 inf 0\nv 0 1 0\nf 1 2 3\n",
    b"mtllib fuzz.mtl\nusemtl red\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n#MTL\nnewmtl red\nKd 1 0 0\nKs 0.5 0.5 0.5\nNs 20\nillum 3\nmap_Kd none.png\n",
    b"o a\ng b\ns 1\nl 1 2\np 1\nv 1 2 3\n",
]


# The scene around a pattern snippet: a camera looking at a sphere on a
# plane, both wearing the texture, lit by one light.
PATTERN_SCENE = """camera { location <0, 1.5, -4> look_at <0, 0.5, 0> }
light_source { <-5, 8, -6> color rgb 1 }
plane { y, -1 texture { %s } }
sphere { <0, 0.5, 0>, 1.2 texture { %s } }
"""

PATTERNS = ["agate", "aoi", "boxed", "bozo", "spotted", "bumps", "cells", "crackle", "cylindrical", "dents",
            "facets", "gradient x", "gradient <1, 2, 0>", "granite", "leopard", "marble", "onion", "planar",
            "quilted", "radial", "ripples", "spherical", "spiral1 3", "spiral2 5", "waves", "wood", "wrinkles",
            "pavement", "tiling 3", "slope y", "slope <0, 1, 1>", "mandel 25", "julia <0.353, 0.288>, 30",
            "magnet 1 mandel 20", "magnet 2 julia <0.3, 0.1>, 20"]
BLOCKS = ["checker", "hexagon", "brick", "square", "triangular", "cubic"]
RAMP = "color_map { [0 rgb <0.1, 0.1, 0.6>] [0.5 rgbf <0.9, 0.2, 0.2, 0.5>] [1 rgbt <1, 0.9, 0.3, 0.2>] }"
MODIFIERS = [
    "turbulence 0.5", "turbulence <1e30, 0, 1>", "turbulence -7", "octaves 0", "octaves 11", "octaves 3",
    "octaves 1e9", "omega 0.7", "omega -5", "omega 1e30", "lambda 0", "lambda 1e10", "lambda -3",
    "frequency 0", "frequency -3", "frequency 1e9", "frequency 1e38", "phase 0.3", "phase -1e8", "ramp_wave",
    "triangle_wave", "sine_wave", "scallop_wave", "cubic_wave", "poly_wave", "poly_wave 0", "poly_wave -2",
    "poly_wave 1e6", "poly_wave 1e-30", "noise_generator 1", "noise_generator 2", "noise_generator 3",
    "agate_turb 1e9", "agate_turb 0", "brick_size <0, 0, 0>", "brick_size <1e-30, 1e30, -1>", "mortar 0",
    "mortar -1", "mortar 10", "form <1e9, -1e9, 3>", "form <0, 0, 0>", "metric 0.001", "metric 1e3",
    "metric 1e30", "offset 1e5", "offset -3", "solid", "coords 1e9", "size 0", "size -1", "size 1e9",
    "exponent 2", "exponent 3", "exponent 4", "exponent 33", "exponent 34", "exterior 7, 0", "exterior 8, -1",
    "exterior 7, 1e20", "exterior 6, 1e30", "exterior 0, 2", "interior 1, 0", "interior 6, 1e30",
    "interior 2, -1", "control0 1e9", "control1 -1e9", "control0 0 control1 0", "number_of_sides 0",
    "number_of_tiles 1e9", "altitude y", "altitude <0, 0, 0>", "scale 0", "scale 1e-30", "scale 1e30",
    "scale <1, 0, 1>", "rotate <1e20, 0, 0>", "translate <1e30, 0, 0>", "matrix <0,0,0, 0,0,0, 0,0,0, 0,0,0>",
]
WARPS = [
    "turbulence 0.5", "turbulence <1e30, 0, 0> octaves 6", "turbulence 1 octaves 0", "turbulence 1 octaves 11",
    "turbulence 1 omega 1e30 lambda 1e30", "turbulence 1 lambda 0", "repeat x", "repeat 0", "repeat x * 1e-30",
    "repeat x * 1e30", "repeat x * 0.5 flip y", "repeat y offset <1e30, 0, 0>", "repeat <1, 1, 0>",
    "repeat -x flip <1, 1, 1>", "black_hole <0, 0, 0>, 1", "black_hole <0, 0, 0>, -1", "black_hole <0, 0, 0>, 0",
    "black_hole <0, 0, 0>, 1e-300", "black_hole <0, 0, 0>, 1e30 falloff 0", "black_hole 0, 1 falloff -5",
    "black_hole 0, 1 falloff 1e6 strength 1e30", "black_hole 0, 0.5 inverse strength -3",
    "black_hole 0, 0.5 repeat <1, 1, 1> turbulence <0.5, 0.5, 0.5>", "black_hole 0, 0.5 repeat <1e-30, 0, 0>",
    "black_hole 0, 0.5 repeat <-1, 1e30, 0>", "cylindrical", "cylindrical orientation y dist_exp 1e6",
    "cylindrical dist_exp -1e6", "cylindrical orientation <0, 0, 0>", "spherical", "spherical dist_exp 2",
    "spherical orientation <1e-300, 0, 0>", "toroidal", "toroidal major_radius 0", "toroidal major_radius -1e30",
    "toroidal dist_exp 300", "planar", "planar y, 0", "planar <0, 0, 0>, 1", "planar z, 1e30", "",
]


def pattern_snippets():
    """Texture bodies: every pattern, block pattern, modifier, warp and map form."""
    for name in PATTERNS:
        yield "pigment { %s %s scale 0.3 }" % (name, RAMP)
        yield "pigment { %s } normal { %s 0.5 scale 0.2 }" % (name, name)
        yield "normal { %s 1 slope_map { [0 <0, 1>] [0.5 <1, 0>] [1 <0, -1>] } }" % name
    for name in BLOCKS:
        yield "pigment { %s scale 0.3 }" % name
        yield "pigment { %s rgb 1, rgb <1, 0, 0>, rgb <0, 0, 1> scale 0.25 }" % name
        yield "pigment { %s pigment { bozo %s } pigment { rgb 0.5 } scale 0.25 }" % (name, RAMP)
        yield "normal { %s 0.5 scale 0.2 }" % name
        yield "normal { %s normal { bumps 1 scale 0.1 } normal { dents 2 } }" % name
        yield "%s texture { pigment { rgb 1 } } texture { pigment { rgb <1, 0, 0> } normal { waves } } scale 0.3" % name
    # Each modifier on three of these (in turn), so the seeds stay few.
    hosts = ("gradient x", "bozo", "crackle", "mandel 30", "wood", "marble", "brick", "quilted", "ripples",
             "facets", "slope y", "spiral1 2", "magnet 1 julia <0.3, 0.1>, 20", "agate", "wrinkles", "hexagon")
    for i, modifier in enumerate(MODIFIERS):
        for name in (hosts[i % len(hosts)], hosts[(i + 5) % len(hosts)], hosts[(i + 11) % len(hosts)]):
            yield "pigment { %s %s %s } normal { %s 0.7 %s }" % (name, modifier, RAMP, name, modifier)
    for warp in WARPS:
        for name in ("checker", "gradient y", "granite", "leopard"):
            yield "pigment { %s %s warp { %s } } normal { %s 1 warp { %s } }" % (name, RAMP, warp, name, warp)
        yield "pigment { onion %s warp { %s } warp { %s } scale 0.2 }" % (RAMP, warp, warp)
        yield "pigment { average warp { %s } pigment_map { [1 gradient x] [2 bozo %s] } }" % (warp, RAMP)
    # color_map in every form.
    yield "pigment { gradient x color_map { } }"
    yield "pigment { gradient x color_map { [0.5 rgb 1] } }"
    yield "pigment { gradient x color_map { [0 0.5 color rgb 1 color rgb 0] [0.5 1 rgb <1, 0, 0> rgb 1] } }"
    yield "pigment { gradient x colour_map { [1 rgb 1] [0 rgb 0] [0.5 rgbft <1, 1, 1, 0.5, 0.5>] } }"
    yield "pigment { gradient x color_map { [-5 rgb 1] [5 rgb 0] } }"
    yield "pigment { gradient x color_map { [0.5 rgb 1] [0.5 rgb 0] [0.5 rgb 0.5] } }"
    yield "pigment { gradient x color_map { [1e30 rgb 1] [-1e30 rgb 0] } }"
    yield "pigment { gradient x color_map { %s } }" % " ".join("[%g rgb %g]" % (i / 300, i / 300) for i in range(300))
    yield "pigment { color_map { [0 rgb 1] [1 rgb 0] } }"
    yield "pigment { rgb 1 color_map { [0 rgb 1] [1 rgb 0] } }"
    yield "pigment { gradient y color_map { [0 rgb 1e30] [1 rgb -1e30] } }"
    # pigment_map, nested, empty and deep.
    yield "pigment { gradient y pigment_map { } }"
    yield "pigment { gradient y pigment_map { [0 checker rgb 1, rgb 0 scale 0.1] [0.5 bozo %s] [1 rgb <0, 0.5, 0>] } }" % RAMP
    deep = "rgb 1"
    for depth in range(40):
        deep = "gradient %s pigment_map { [0 %s] [1 rgb %g] } scale 1.3" % ("xyz"[depth % 3], deep, depth / 40)
    yield "pigment { %s }" % deep
    yield "pigment { average }"
    yield "pigment { average pigment_map { [0 rgb 1] [0 rgb 0] } }"
    yield "pigment { average pigment_map { [1 rgb 1] [-1 rgb 0] } }"
    yield "pigment { average pigment_map { [1e30 rgb 1] [-1e30 rgb 0] } }"
    # normal_map, slope_map, average normals.
    yield "normal { gradient x normal_map { [0.3 bumps 0.6 scale 0.05] [0.7 dents 0.8 scale 0.1] } }"
    yield "normal { gradient x normal_map { } }"
    yield "normal { gradient x slope_map { } }"
    yield "normal { gradient x 1e30 slope_map { [0 <1e30, -1e30>] [1 <0, 1e30>] } }"
    yield "normal { gradient x 1 slope_map { [1 <0, 1>] [0 <1, 0>] } accuracy 1e-30 }"
    yield "normal { gradient x 1 accuracy 0 }"
    yield "normal { gradient x 1 accuracy -1 }"
    yield "normal { gradient x 1 accuracy 1e30 }"
    yield "normal { bumps 1e30 }"
    yield "normal { bumps -1e30 }"
    yield "normal { wrinkles 0 bump_size 1e38 }"
    yield "normal { average normal_map { [1 bumps 1] [1 dents 1] [-2 waves 1] } }"
    yield "normal { average normal_map { [0 bumps 1] } }"
    yield "normal { average }"
    deep = "bumps 0.5"
    for depth in range(40):
        deep = "gradient %s normal_map { [0 %s] [1 waves %g] } scale 1.3" % ("xyz"[depth % 3], deep, depth / 40)
    yield "normal { %s }" % deep
    # texture_map, block lists of textures, layered textures.
    yield "gradient x texture_map { [0 pigment { rgb 1 } normal { bumps }] [1 pigment { bozo %s } finish { phong 1 }] }" % RAMP
    yield "gradient x texture_map { }"
    yield ("bozo texture_map { [0 gradient y texture_map { [0 pigment { rgb 1 }] [1 pigment { rgb 0 }] }] "
           "[1 pigment { rgbt <1, 0, 0, 0.5> }] } scale 0.2")
    yield "pigment { rgb 1 } } texture { pigment { bozo color_map { [0 rgbt 1] [1 rgb <1, 0, 0>] } } normal { dents }"
    yield "pigment { rgbf <1, 0, 0, 1> } } texture { pigment { rgbt 1 } } texture { pigment { checker rgbt 0.5, rgb 1 }"


def main() -> None:
    out = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else "fuzz-corpus")
    scene_dir, obj_dir = out / "scene", out / "obj"
    for path in sorted(ROOT.glob("scenes/**/*.pov")) + sorted(ROOT.glob("include/*.inc")):
        save(scene_dir, path.read_bytes())
    for test in sorted(ROOT.glob("parser/src/*_test.cpp")):
        for scene in test_scenes(test.read_text(errors="replace")):
            save(scene_dir, scene)
    regressions = ROOT / "tests/fuzz/regressions"
    for path in sorted(regressions.glob("*.pov")):
        save(scene_dir, path.read_bytes())
    for path in sorted(ROOT.glob("scenes/**/*.obj")) + sorted(regressions.glob("*.obj")):
        data = path.read_bytes()
        mtl = path.with_suffix(".mtl")
        if mtl.exists():
            data = data.replace(b"mtllib " + mtl.name.encode(), b"mtllib fuzz.mtl") + b"\n#MTL\n" + mtl.read_bytes()
        save(obj_dir, data)
    for case in OBJ_CASES:
        save(obj_dir, case)
    shapes_dir = out / "shapes"
    for kind in range(18):
        stream = bytes((kind * 37 + 11 * i) % 256 for i in range(400))
        save(shapes_dir, bytes([kind]) + stream)
    for path in sorted(regressions.glob("*.shapes")):
        save(shapes_dir, path.read_bytes())

    patterns_dir = out / "patterns"
    for path in sorted(ROOT.glob("tests/reference/pov/patterns_*.pov")) + [ROOT / "tests/reference/pov/normals.pov"]:
        save(patterns_dir, path.read_bytes())
    for snippet in pattern_snippets():
        save(patterns_dir, (PATTERN_SCENE % (snippet, snippet)).encode())
    # Global settings the patterns read.
    for settings in ("number_of_waves 2000000000", "number_of_waves 0", "number_of_waves -5", "noise_generator 3",
                     "noise_generator 1"):
        for snippet in ("pigment { ripples }", "normal { waves 1 }", "pigment { bozo turbulence 1 }"):
            save(patterns_dir, (("global_settings { %s }\n" % settings) + PATTERN_SCENE % (snippet, snippet)).encode())
    for path in sorted(regressions.glob("*.patterns")):
        save(patterns_dir, path.read_bytes())

    # Dictionary: quoted token aliases in the grammar ("sphere", "{", ...) and directives.
    grammar = (ROOT / "parser/src/grammar.y").read_text()
    words = sorted(set(re.findall(r'\b[A-Z_0-9]+ "([^"\s\\]+)"', grammar)))
    words += ["#declare", "#local", "#include", "#if", "#else", "#elseif", "#end", "#while", "#for",
              "#macro", "#switch", "#case", "#range", "#break", "#ifdef", "#ifndef", "#undef",
              "#version", "#debug", "#warning", "#error", "#default", "/*", "*/", "//"]
    with open(out / "scene.dict", "w") as d:
        for w in words:
            d.write('"' + w.replace("\\", "\\\\").replace('"', '\\"') + '"\n')
    counts = {d.name: len(list(d.iterdir())) for d in (scene_dir, obj_dir, shapes_dir, patterns_dir)}
    print(f"corpus in {out}: {counts['scene']} scene seeds, {counts['obj']} OBJ seeds, "
          f"{counts['patterns']} pattern seeds, {len(words)} dictionary words")


if __name__ == "__main__":
    main()
