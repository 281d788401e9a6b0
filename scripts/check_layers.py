#!/usr/bin/env python3
"""Checks Prism's library layering and draws it.

Reads the link graph CMake writes at configure time (<build>/prism_link_graph.txt: one line
"target layer dep1 dep2 ..." per library, catalogue and app) and fails when a dependency
points upward: a library may link only libraries of its own layer or of layers below
(cpu < gl < render < systems < scenes < apps). CPU-layer libraries therefore link no GL.
It also checks that no header or source of a library includes a header of a library it
does not link (include path = library), that no file of runtime/, apps/ or examples/
includes a private header of the shader tool (shaderc_tool/src/; the tool's public API is
prism/shaderc/), that no code in runtime/ or apps/ creates or deletes a GL object except
through prism/gl/handles.hpp, and draws the graph as docs/architecture.svg.

    python3 scripts/check_layers.py build                 # check; exit 1 on a violation
    python3 scripts/check_layers.py build --write-svg     # also rewrite docs/architecture.svg
    python3 scripts/check_layers.py build --check-svg     # fail when the SVG is out of date
    python3 scripts/check_layers.py --private-includes TREE  # only the shaderc_tool/src rule, on TREE
"""
import html
import os
import re
import sys

LAYERS = ["cpu", "gl", "render", "systems", "scenes", "apps"]
ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
SVG_PATH = os.path.join(ROOT, "docs", "architecture.svg")

# Which folder of include/prism/<dir>/ each library owns (include path = library).
INCLUDE_DIR_OWNERS = {
    "catalog": ["prism_catalog"], "geometry": ["prism_geometry"], "image": ["prism_image"],
    "view": ["prism_view"], "gl": ["prism_gl"], "render": ["prism_render"],
    "rain": ["prism_rain_core", "prism_rain"], "water": ["prism_water_core", "prism_water"],
    "scene": ["prism_scene_core", "prism_scene"], "shaderc": ["prism_shaderc_lib"],
}
# Code that must reach the shader tool only through its public API, prism/shaderc/.
TOOL_CLIENT_FOLDERS = ["runtime", "apps", "examples"]
# Source folders of each library, for the include check.
LIBRARY_SOURCES = {
    "prism_image": ["runtime/image"], "prism_view": ["runtime/view"], "prism_geometry": ["runtime/geometry"],
    "prism_gl": ["runtime/gl"], "prism_render": ["runtime/render"],
}


def read_graph(build_dir):
    path = os.path.join(build_dir, "prism_link_graph.txt")
    if not os.path.exists(path):
        sys.exit(f"{path}: not found; configure the build first (cmake -S . -B {build_dir})")
    graph = {}
    for number, line in enumerate(open(path), 1):
        parts = line.split()
        if not parts:
            continue
        if len(parts) < 2 or parts[1] not in LAYERS:
            sys.exit(f"{path}:{number}: error: expected 'target layer deps...', got '{line.strip()}'")
        graph[parts[0]] = (parts[1], parts[2:])
    return graph


def closure(graph, target):
    seen, todo = set(), list(graph[target][1])
    while todo:
        d = todo.pop()
        if d in seen or d not in graph:
            continue
        seen.add(d)
        todo.extend(graph[d][1])
    return seen


def upward_edges(graph):
    errors = []
    for target, (layer, deps) in sorted(graph.items()):
        for dep in deps:
            dep_layer = graph[dep][0]
            if LAYERS.index(dep_layer) > LAYERS.index(layer):
                errors.append(f"{target} ({layer}) links {dep} ({dep_layer}): a dependency may not point "
                              f"upward; move the shared code down to the {layer} layer or below")
    return errors


def include_errors(graph):
    """A library's files may include prism/<dir>/ headers only of libraries it links."""
    errors = []
    include_re = re.compile(r'#include\s+"prism/(\w+)/')
    for lib, folders in LIBRARY_SOURCES.items():
        if lib not in graph:
            continue
        allowed = closure(graph, lib) | {lib}
        for folder in folders:
            for dirpath, _, files in os.walk(os.path.join(ROOT, folder)):
                for name in files:
                    path = os.path.join(dirpath, name)
                    for number, line in enumerate(open(path, encoding="utf-8"), 1):
                        m = include_re.search(line)
                        if not m or m.group(1) not in INCLUDE_DIR_OWNERS:
                            continue
                        owners = INCLUDE_DIR_OWNERS[m.group(1)]
                        if not any(o in allowed for o in owners):
                            rel = os.path.relpath(path, ROOT)
                            errors.append(f"{rel}:{number}: error: {lib} includes prism/{m.group(1)}/ but does "
                                          f"not link {' or '.join(owners)}")
    return errors


def private_include_errors(root):
    """No file under TOOL_CLIENT_FOLDERS includes a header of shaderc_tool/src/, by path or by
    bare name (a name found there and not beside the including file)."""
    private_dir = os.path.join(root, "shaderc_tool", "src")
    include_re = re.compile(r'^\s*#\s*include\s+"([^"]+)"')
    errors = []
    for top in TOOL_CLIENT_FOLDERS:
        for dirpath, _, files in os.walk(os.path.join(root, top)):
            for name in files:
                if not name.endswith((".cpp", ".hpp", ".h")):
                    continue
                path = os.path.join(dirpath, name)
                for number, line in enumerate(open(path, encoding="utf-8"), 1):
                    m = include_re.match(line)
                    if not m:
                        continue
                    target = m.group(1)
                    by_path = "shaderc_tool/src/" in target
                    by_name = (os.path.exists(os.path.join(private_dir, target))
                               and not os.path.exists(os.path.join(dirpath, target)))
                    if by_path or by_name:
                        rel = os.path.relpath(path, root)
                        errors.append(f"{rel}:{number}: error: includes \"{target}\", a private header of the shader "
                                      f"tool (shaderc_tool/src/); use its public API, prism/shaderc/build_step.hpp")
    return errors


def raw_gl_object_errors():
    """Every GL object in runtime/ and apps/ is owned through prism/gl/handles.hpp: no raw
    glGen*/glDelete*/glCreateShader/glCreateProgram outside runtime/gl/src/handles.cpp."""
    raw = re.compile(r"\b(glGen(Buffers|Textures|VertexArrays|Framebuffers|Renderbuffers|Queries)|"
                     r"glDelete(Buffers|Textures|VertexArrays|Framebuffers|Renderbuffers|Queries|Shader|Program)|"
                     r"glCreate(Shader|Program))\s*\(")
    errors = []
    for top in ("runtime", "apps"):
        for dirpath, _, files in os.walk(os.path.join(ROOT, top)):
            for name in files:
                path = os.path.join(dirpath, name)
                rel = os.path.relpath(path, ROOT)
                if rel == os.path.join("runtime", "gl", "src", "handles.cpp") or not name.endswith((".cpp", ".hpp")):
                    continue
                for number, line in enumerate(open(path, encoding="utf-8"), 1):
                    m = raw.search(line.split("//")[0])
                    if m:
                        errors.append(f"{rel}:{number}: error: raw {m.group(1)}; own GL objects through "
                                      f"prism::gl handles (prism/gl/handles.hpp)")
    return errors


def draw_svg(graph):
    """Layers as rows (apps on top, cpu at the bottom), one box per library, an arrow per link."""
    box_w, box_h, gap_x, row_h, margin = 150, 30, 14, 110, 20
    rows = {layer: sorted(t for t, (l, _) in graph.items() if l == layer) for layer in LAYERS}
    width = margin * 2 + 90 + max(len(r) for r in rows.values()) * (box_w + gap_x)
    height = margin * 2 + row_h * len(LAYERS)
    pos = {}
    for i, layer in enumerate(reversed(LAYERS)):
        y = margin + i * row_h + 20
        for j, target in enumerate(rows[layer]):
            pos[target] = (margin + 90 + j * (box_w + gap_x), y)
    out = [f'<svg xmlns="http://www.w3.org/2000/svg" width="{width}" height="{height}" '
           f'font-family="sans-serif" font-size="11">',
           '<defs><marker id="a" markerWidth="8" markerHeight="8" refX="7" refY="4" orient="auto">'
           '<path d="M0,0 L8,4 L0,8 z" fill="#667"/></marker></defs>',
           f'<rect width="{width}" height="{height}" fill="white"/>']
    for i, layer in enumerate(reversed(LAYERS)):
        y = margin + i * row_h
        out.append(f'<rect x="{margin}" y="{y}" width="{width - 2 * margin}" height="{row_h - 10}" '
                   f'fill="{"#f4f6fb" if i % 2 else "#eef3ee"}"/>')
        out.append(f'<text x="{margin + 6}" y="{y + 40}" font-weight="bold">{layer}</text>')
    for target, (_, deps) in sorted(graph.items()):
        x0, y0 = pos[target]
        for dep in deps:
            x1, y1 = pos[dep]
            if y1 == y0:  # same layer: a curved arrow below the boxes
                out.append(f'<path d="M{x0 + box_w / 2},{y0 + box_h} C{x0 + box_w / 2},{y0 + box_h + 30} '
                           f'{x1 + box_w / 2},{y1 + box_h + 30} {x1 + box_w / 2},{y1 + box_h + 2}" fill="none" '
                           f'stroke="#99a" marker-end="url(#a)"><title>{target} -&gt; {dep}</title></path>')
            else:
                out.append(f'<line x1="{x0 + box_w / 2}" y1="{y0 + box_h}" x2="{x1 + box_w / 2}" y2="{y1 - 2}" '
                           f'stroke="#99a" marker-end="url(#a)"><title>{target} -&gt; {dep}</title></line>')
    for target, (x, y) in sorted(pos.items()):
        out.append(f'<rect x="{x}" y="{y}" width="{box_w}" height="{box_h}" rx="4" fill="#fff" stroke="#334"/>')
        out.append(f'<text x="{x + box_w / 2}" y="{y + 19}" text-anchor="middle">{html.escape(target)}</text>')
    out.append("</svg>")
    return "\n".join(out) + "\n"


def main(argv):
    if len(argv) < 2:
        sys.exit(__doc__)
    if argv[1] == "--private-includes" and len(argv) == 3:
        errors = private_include_errors(argv[2])
        for e in errors:
            print(e, file=sys.stderr)
        return 1 if errors else 0
    graph = read_graph(argv[1])
    errors = upward_edges(graph) + include_errors(graph) + private_include_errors(ROOT) + raw_gl_object_errors()
    svg = draw_svg(graph)
    if "--write-svg" in argv:
        open(SVG_PATH, "w").write(svg)
    if "--check-svg" in argv:
        current = open(SVG_PATH).read() if os.path.exists(SVG_PATH) else ""
        if current != svg:
            errors.append("docs/architecture.svg does not match the link graph; rerun "
                          "`python3 scripts/check_layers.py build --write-svg` and commit it")
    for e in errors:
        print(e if ": error:" in e else f"error: {e}", file=sys.stderr)
    if errors:
        return 1
    print(f"check_layers: {len(graph)} targets, {sum(len(d) for _, d in graph.values())} links, none upward")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
