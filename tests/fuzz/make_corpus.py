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
    for kind in range(16):
        stream = bytes((kind * 37 + 11 * i) % 256 for i in range(400))
        save(shapes_dir, bytes([kind]) + stream)
    for path in sorted(regressions.glob("*.shapes")):
        save(shapes_dir, path.read_bytes())

    # Dictionary: quoted token aliases in the grammar ("sphere", "{", ...) and directives.
    grammar = (ROOT / "parser/src/grammar.y").read_text()
    words = sorted(set(re.findall(r'\b[A-Z_]+ "([^"\s\\]+)"', grammar)))
    words += ["#declare", "#local", "#include", "#if", "#else", "#elseif", "#end", "#while", "#for",
              "#macro", "#switch", "#case", "#range", "#break", "#ifdef", "#ifndef", "#undef",
              "#version", "#debug", "#warning", "#error", "#default", "/*", "*/", "//"]
    with open(out / "scene.dict", "w") as d:
        for w in words:
            d.write('"' + w.replace("\\", "\\\\").replace('"', '\\"') + '"\n')
    counts = {d.name: len(list(d.iterdir())) for d in (scene_dir, obj_dir, shapes_dir)}
    print(f"corpus in {out}: {counts['scene']} scene seeds, {counts['obj']} OBJ seeds, {len(words)} dictionary words")


if __name__ == "__main__":
    main()
