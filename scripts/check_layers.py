#!/usr/bin/env python3
"""Checks Prism's library layering and draws it.

Reads the link graph CMake writes at configure time (<build>/prism_link_graph.txt: one line
"target layer dep1 dep2 ..." per library, catalogue and app) and fails when a dependency
points upward: a library may link only libraries of its own layer or of layers below
(cpu < gl < render < systems < scenes < apps). CPU-layer libraries therefore link no GL.
It also checks that no header or source of a library includes a header of a library it
does not link (include path = library), that no file of runtime/, apps/ or examples/
includes a private header of the shader tool (shaderc_tool/src/; the tool's public API is
prism/shaderc/), that nothing outside shaderc_tool/ includes from shaderc_tool/include/ but prism/shaderc/
(the headers the tool and the runtime share are the foundation's, foundation/), that no file of
shaderc_tool/src/ includes one of a later stage of the tool (TOOL_STAGES, in runTool()'s order), that
no code in runtime/ or apps/ creates or deletes a GL object except through prism/gl/handles.hpp, and
draws the graph as docs/architecture.svg.

    python3 scripts/check_layers.py build                 # check; exit 1 on a violation
    python3 scripts/check_layers.py build --write-svg     # also rewrite docs/architecture.svg
    python3 scripts/check_layers.py build --check-svg     # fail when the SVG is out of date
    python3 scripts/check_layers.py --private-includes TREE  # only the shaderc_tool/src rule, on TREE
    python3 scripts/check_layers.py --self-test           # the tool's stage and include rules on a made-up tree
"""
import html
import os
import re
import sys

LAYERS = ["cpu", "gl", "render", "systems", "scenes", "apps"]
ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
SVG_PATH = os.path.join(ROOT, "docs", "architecture.svg")

# The foundation: libraries the tool and the runtime share, each in foundation/<dir>/ with its headers
# in foundation/<dir>/include/prism/<dir>/ (include path = library = namespace). Drawn apart in the picture.
FOUNDATION_LIBRARIES = {"prism_catalog": "foundation/catalog", "prism_io": "foundation/io",
                        "prism_hash": "foundation/hash"}
FOUNDATION_FILL = "#fbe3b0"
# Which folder of include/prism/<dir>/ each library owns (include path = library).
INCLUDE_DIR_OWNERS = {
    "catalog": ["prism_catalog"], "io": ["prism_io"], "hash": ["prism_hash"],
    "geometry": ["prism_geometry"], "image": ["prism_image"],
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
    **{lib: [folder] for lib, folder in FOUNDATION_LIBRARIES.items()},
}
# The one public include folder of the tool that code outside shaderc_tool/ may use; every other
# shared header is the foundation's.
TOOL_PUBLIC_INCLUDES = ["shaderc"]
SOURCE_SUFFIXES = (".cpp", ".hpp", ".h", ".in")

# The stage of each file of shaderc_tool/src/ (x.hpp and x.cpp share their stem's), in runTool()'s
# order (shaderc_tool/src/tool.cpp's header comment). A file includes only files of its own stage or
# an earlier one, so no stage reaches into a later one. 0: shared by every stage, no step of its own;
# 7: the entries that run the stages (the tool, the build step of prism/shaderc/).
TOOL_SRC = "shaderc_tool/src"
TOOL_STAGES = {
    0: "diagnostics did_you_mean directive_lines data_file_records generated_format glslang_stage "
       "job_pool module_naming output_file source_reader spirv_words stage_files tool_identity",
    1: "args output_options path_embedding program_argument shown_path spirv_env target_rules targets",  # the command line
    2: "code_signature source_fingerprint up_to_date",  # nothing changed?
    3: "contract program_declarations shader_inputs",  # the inputs and the contract
    4: "catalog_builder catalog_model glslang_preprocessor include_resolver include_search preprocessor_limits "
       "reflection structural_macros validation_key variant_resolution variants",  # includes and variants
    5: "assigned_locations contract_check es300_limits es300_target interface_check shader_targets shared_stage_parses "
       "spirv_codegen spirv_source_lines spirv_target stage_interface target_scheduler validation_cache "
       "validation_scheduler validation_settings validator vulkan_reflection vulkan_stage_rules",  # validation, targets
    6: "block_structs data_writer depfile generator_glsl generator_header generator_reflection generator_spirv "
       "generator_web glsl_emitter header_writer output_generator output_generators outputs reflection_writer "
       "web_writer",  # outputs
    7: "build_step builtin_contract tool",
}
# Upward includes a change in flight may leave for a while (none now: issue 39 removed the last),
# reported on every run; an entry that no longer occurs is an error, so the list only shrinks.
PENDING_UPWARD_INCLUDES = {}


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


def foreign_tool_include_errors(root):
    """The foundation's headers live in foundation/, not in the tool: shaderc_tool/include/prism/ holds only
    TOOL_PUBLIC_INCLUDES, and no file outside shaderc_tool/ includes anything else from shaderc_tool/include/."""
    errors = []
    tool_include = os.path.join(root, "shaderc_tool", "include", "prism")
    tool_dirs = sorted(os.listdir(tool_include)) if os.path.isdir(tool_include) else []
    for d in tool_dirs:
        if d not in TOOL_PUBLIC_INCLUDES:
            errors.append(f"shaderc_tool/include/prism/{d}: error: only prism/{'/, prism/'.join(TOOL_PUBLIC_INCLUDES)}/ "
                          f"is the tool's; a header the runtime shares belongs in foundation/<library>/include/")
    include_re = re.compile(r'^\s*#\s*include\s+["<]([^">]+)[">]')
    for top in sorted(os.listdir(root)):
        if top == "shaderc_tool" or top.startswith((".", "build", "cmake-build", "out")):
            continue
        for dirpath, _, files in os.walk(os.path.join(root, top)):
            for name in files:
                if not name.endswith(SOURCE_SUFFIXES):
                    continue
                path = os.path.join(dirpath, name)
                for number, line in enumerate(open(path, encoding="utf-8", errors="replace"), 1):
                    m = include_re.match(line)
                    if not m:
                        continue
                    target = m.group(1).split("shaderc_tool/include/", 1)[-1]
                    parts = target.split("/")
                    by_path = "shaderc_tool/include/" in m.group(1)
                    if (by_path or (len(parts) > 2 and parts[0] == "prism" and parts[1] in tool_dirs)) and \
                            not (len(parts) > 2 and parts[1] in TOOL_PUBLIC_INCLUDES):
                        errors.append(f"{os.path.relpath(path, root)}:{number}: error: includes \"{m.group(1)}\" "
                                      f"from shaderc_tool/include/; outside the tool only prism/shaderc/ is its to give")
    return errors


def tool_stage_errors(root, stages=None, pending=None):
    """No file of shaderc_tool/src/ includes one of a later stage (TOOL_STAGES). Returns (errors, notes):
    notes for the PENDING_UPWARD_INCLUDES still there, an error for one that no longer occurs."""
    stages = TOOL_STAGES if stages is None else stages
    pending = PENDING_UPWARD_INCLUDES if pending is None else pending
    stage_of = {stem: stage for stage, stems in stages.items() for stem in stems.split()}
    src = os.path.join(root, TOOL_SRC)
    include_re = re.compile(r'^\s*#\s*include\s+"([^"/]+)"')
    errors, notes, seen = [], [], set()
    for name in sorted(os.listdir(src)):
        if not name.endswith(SOURCE_SUFFIXES):
            continue
        rel = f"{TOOL_SRC}/{name}"
        stem = name.split(".")[0]
        if stem not in stage_of:
            errors.append(f"{rel}:1: error: has no stage; add '{stem}' to TOOL_STAGES in scripts/check_layers.py")
            continue
        for number, line in enumerate(open(os.path.join(src, name), encoding="utf-8"), 1):
            m = include_re.match(line)
            target = m.group(1) if m else ""
            if not m or target.split(".")[0] not in stage_of or not os.path.exists(os.path.join(src, target)):
                continue
            mine, theirs = stage_of[stem], stage_of[target.split(".")[0]]
            if theirs <= mine:
                continue
            if (name, target) in pending:
                seen.add((name, target))
                notes.append(f"{rel}:{number}: note: pending upward include of \"{target}\" (stage {theirs} from "
                             f"stage {mine}): {pending[(name, target)]}")
                continue
            where = "to the shared files (stage 0)" if mine == 0 else f"to stage {mine} or to the shared files (stage 0)"
            errors.append(f"{rel}:{number}: error: stage {mine} includes \"{target}\" of stage {theirs}, a later "
                          f"one; move what it needs down {where}")
    for name, target in sorted(set(pending) - seen):
        errors.append(f"{TOOL_SRC}/{name}: error: PENDING_UPWARD_INCLUDES lists its include of \"{target}\", which "
                      f"is gone; remove the entry from scripts/check_layers.py")
    return errors, notes


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


def self_test():
    """The two tool rules on a made-up tree: each violation named, each allowed include passed."""
    import tempfile
    files = {
        "shaderc_tool/src/early.cpp": '#include "early.hpp"\n#include "shared.hpp"\n#include "late.hpp"\n',
        "shaderc_tool/src/early.hpp": '#include "shared.hpp"\n#include "later.hpp"\n',
        "shaderc_tool/src/late.hpp": '#include "early.hpp"\n', "shaderc_tool/src/later.hpp": "",
        "shaderc_tool/src/shared.hpp": '#include "early.hpp"\n', "shaderc_tool/src/stray.cpp": "",
        "shaderc_tool/include/prism/shaderc/tool.hpp": "", "shaderc_tool/include/prism/catalog/types.hpp": "",
        "runtime/x/src/a.cpp": '#include "prism/shaderc/tool.hpp"\n#include "prism/catalog/types.hpp"\n'
                               '#include "prism/gl/handles.hpp"\n#include "../../../shaderc_tool/include/prism/x.hpp"\n',
    }
    stages = {0: "shared", 1: "early", 2: "late later"}
    pending = {("early.hpp", "later.hpp"): "someone", ("late.hpp", "gone.hpp"): "someone"}
    with tempfile.TemporaryDirectory() as root:
        for rel, text in files.items():
            os.makedirs(os.path.dirname(os.path.join(root, rel)), exist_ok=True)
            open(os.path.join(root, rel), "w").write(text)
        errors, notes = tool_stage_errors(root, stages, pending)
        errors += foreign_tool_include_errors(root)
    wanted = ['early.cpp:3: error: stage 1 includes "late.hpp" of stage 2', 'shared.hpp:1: error: stage 0 includes',
              "stray.cpp:1: error: has no stage", 'late.hpp: error: PENDING_UPWARD_INCLUDES lists its include of "gone',
              "shaderc_tool/include/prism/catalog: error:", 'runtime/x/src/a.cpp:2: error: includes "prism/catalog/',
              "runtime/x/src/a.cpp:4: error: includes"]
    text = "\n".join(errors + notes)
    missing = [w for w in wanted if w not in text]
    unwanted = [e for e in errors if not any(w in e for w in wanted)]
    if missing or unwanted or len(notes) != 1 or "early.hpp:2: note: pending" not in notes[0]:
        print(text + "\nself-test: error: missing " + repr(missing) + ", unexpected " + repr(unwanted))
        return 1
    print(text + "\nself-test: OK: every upward and foreign include named, the allowed ones passed")
    return 0


def draw_svg(graph):
    """Layers as rows (apps on top, cpu at the bottom), one box per library, an arrow per link; the
    foundation's libraries (FOUNDATION_LIBRARIES) in amber."""
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
        if layer == "cpu":  # the key to the foundation's boxes
            out.append(f'<rect x="{margin + 6}" y="{y + 52}" width="10" height="10" fill="{FOUNDATION_FILL}" '
                       f'stroke="#334"/><text x="{margin + 20}" y="{y + 61}">foundation/</text>')
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
        fill = FOUNDATION_FILL if target in FOUNDATION_LIBRARIES else "#fff"
        out.append(f'<rect x="{x}" y="{y}" width="{box_w}" height="{box_h}" rx="4" fill="{fill}" stroke="#334"/>')
        out.append(f'<text x="{x + box_w / 2}" y="{y + 19}" text-anchor="middle">{html.escape(target)}</text>')
    out.append("</svg>")
    return "\n".join(out) + "\n"


def main(argv):
    if len(argv) < 2:
        sys.exit(__doc__)
    if argv[1] == "--self-test":
        return self_test()
    if argv[1] == "--private-includes" and len(argv) == 3:
        errors = private_include_errors(argv[2])
        for e in errors:
            print(e, file=sys.stderr)
        return 1 if errors else 0
    graph = read_graph(argv[1])
    stage_errors, pending_notes = tool_stage_errors(ROOT)
    errors = (upward_edges(graph) + include_errors(graph) + private_include_errors(ROOT) + raw_gl_object_errors() +
              foreign_tool_include_errors(ROOT) + stage_errors)
    for note in pending_notes:
        print(note)
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
