#!/usr/bin/env python3
"""Compile tests for every resource kind of the includes, and SPIR-V checks of the bindless hook.

usage: compile_resources.py --list
       compile_resources.py GLSLANG GLSLC SPIRV_DIS INCLUDE_DIR GROUP
Groups (each its own ctest entry, tests/CMakeLists.txt):
  compile.KIND.STAGE.COMPILER  one shader of stage frag / comp / rgen (#version 460) that calls every family
                               applicable to KIND (the table below, docs/API.md "Resources"), compiled by
                               glslangValidator or glslc (Vulkan 1.2, glslc -Werror);
  resources.KIND               TF_RESOURCES subsets: KIND's shader compiles with only KIND's bit set, and fails
                               with every bit but KIND's, each error a "no matching overloaded function" (a family
                               called with a kind that was left out), both compilers;
  nonuniform.KIND              bindless: the KIND shader over arrays of its textures indexed with
                               nonuniformEXT(k), `#define TF_NONUNIFORM nonuniformEXT`, both compilers (glslc
                               also with -O): every image instruction's image operand is NonUniform (rule below);
                               and without TF_NONUNIFORM (unoptimised: calls are not inlined) some image
                               operand inside the includes is not, so the check can fail.
Standard library only. Everything a test shader declares comes after the include: an include must not
depend on what the user declares.
"""
import os
import re
import subprocess
import sys
import tempfile

STAGES = ("frag", "comp", "rgen")
COMPILERS = ("glslangValidator", "glslc")

# Resource kinds: the textures each declares (type, name; samplers are never arrays in the bindless
# shader), the TF_RESOURCES bit, and the forms its calls take. A form: texture arguments T (first), the
# extras X right after uv / texel, and which call sets apply: manual (every manual family, the _level
# forms, tf_fetch), queries (tf_lod, tf_lod_unclamped, tf_level_size), hw (the _hw forms); sat: the
# SAT's table arguments and extras.
KINDS = {
    "combined": dict(bit="TF_RESOURCE_SAMPLER_2D",
                     textures=[("sampler2D", "tex"), ("usampler2D", "satLow"), ("usampler2D", "satHigh")],
                     forms=[dict(T="tex", X="", manual=True, queries=True, hw=True)],
                     sat=dict(T="satLow, satHigh", X="")),
    "separate": dict(bit="TF_RESOURCE_TEXTURE_2D",
                     textures=[("texture2D", "tex"), ("utexture2D", "satLow"), ("utexture2D", "satHigh")],
                     forms=[dict(T="tex", X="", manual=True, queries=True, hw=False)],
                     sat=dict(T="satLow, satHigh", X="")),
    "separate-hw": dict(bit="TF_RESOURCE_TEXTURE_2D",
                        textures=[("texture2D", "tex"), ("sampler", "smp")],
                        forms=[dict(T="tex, smp", X="", manual=False, queries=False, hw=True)]),
    "array": dict(bit="TF_RESOURCE_SAMPLER_2D_ARRAY",
                  textures=[("sampler2DArray", "tex"), ("usampler2DArray", "satLow"), ("usampler2DArray", "satHigh")],
                  forms=[dict(T="tex", X=", layer", manual=True, queries=True, hw=True)],
                  sat=dict(T="satLow, satHigh", X=", layer")),
    "separate-array": dict(bit="TF_RESOURCE_TEXTURE_2D_ARRAY",
                           textures=[("texture2DArray", "tex"), ("utexture2DArray", "satLow"),
                                     ("utexture2DArray", "satHigh")],
                           forms=[dict(T="tex", X=", layer", manual=True, queries=True, hw=False)],
                           sat=dict(T="satLow, satHigh", X=", layer")),
    "separate-array-hw": dict(bit="TF_RESOURCE_TEXTURE_2D_ARRAY",
                              textures=[("texture2DArray", "tex"), ("sampler", "smp")],
                              forms=[dict(T="tex, smp", X=", layer", manual=False, queries=False, hw=True)]),
    "integer-u": dict(bit="TF_RESOURCE_INTEGER",
                      textures=[("usampler2D", "tex"), ("utexture2D", "tex2")],
                      forms=[dict(T="tex", X="", manual=True, queries=True, hw=False),
                             dict(T="tex2", X="", manual=True, queries=True, hw=False)]),
    "integer-i": dict(bit="TF_RESOURCE_INTEGER",
                      textures=[("isampler2D", "tex"), ("itexture2D", "tex2")],
                      forms=[dict(T="tex", X="", manual=True, queries=True, hw=False),
                             dict(T="tex2", X="", manual=True, queries=True, hw=False)]),
    "shadow": dict(bit="TF_RESOURCE_SHADOW",
                   textures=[("sampler2D", "depth"), ("texture2D", "depth2")],
                   forms=[dict(T="depth", X=", cmp", manual=True, queries=False, hw=False),
                          dict(T="depth2", X=", cmp", manual=True, queries=False, hw=False)]),
    # Cube maps (cube.glsl): one kind with both cube bits, fragment only (compile_includes compiles
    # cube.glsl with a samplerCube in every stage). Its two forms take both remaining paths: a separate sampler
    # (the sampled-image constructor) and an array (the layer), every family's manual and _hw entry points.
    "cube": dict(bit="TF_RESOURCE_CUBE | TF_RESOURCE_CUBE_ARRAY", stages=("frag",),
                 textures=[("textureCube", "tex"), ("sampler", "smp"), ("samplerCubeArray", "tex2")],
                 forms=[], cube=[dict(T="tex, smp", X=""), dict(T="tex2", X=", layer")]),
    "shadow-hw": dict(bit="TF_RESOURCE_SHADOW",
                      textures=[("sampler2DShadow", "shadowTex"), ("texture2D", "depth"), ("samplerShadow", "smp")],
                      forms=[dict(T="shadowTex", X=", dref", manual=False, queries=False, hw=True),
                             dict(T="depth, smp", X=", dref", manual=False, queries=False, hw=True)]),
}
# The user's texel source (docs/API.md "Texel sources"): TF_SOURCE, not a TF_RESOURCES bit. A tile of an atlas
# as the user declares it before the include; its shader calls every manual family with `src`.
KINDS["source"] = dict(bit=None, textures=[],
                       forms=[dict(T="src", X="", manual=True, queries=True, hw=False)])
SOURCE_PRELUDE = """layout(set = 0, binding = 7) uniform sampler2D atlas;
struct Tile { ivec2 origin, size; int levels; };
#define TF_SOURCE Tile
ivec2 tf_source_size(Tile t, int level) { return max(t.size >> level, ivec2(1)); }
int tf_source_levels(Tile t) { return t.levels; }
vec4 tf_source_fetch(Tile t, ivec2 texel, int level) { return texelFetch(atlas, (t.origin >> level) + texel, level); }"""
SAMPLER_TYPES = ("sampler", "samplerShadow")
BITS = {"TF_RESOURCE_SAMPLER_2D": 1, "TF_RESOURCE_TEXTURE_2D": 2, "TF_RESOURCE_SAMPLER_2D_ARRAY": 4,
        "TF_RESOURCE_TEXTURE_2D_ARRAY": 8, "TF_RESOURCE_INTEGER": 16, "TF_RESOURCE_SHADOW": 32,
        "TF_RESOURCE_CUBE": 64, "TF_RESOURCE_CUBE_ARRAY": 128, "TF_RESOURCE_LATLONG": 256,
        "TF_RESOURCE_CUBE | TF_RESOURCE_CUBE_ARRAY": 192}
ALL_BITS = 511


def calls(kind):
    """Every call KIND's shader makes, as vec4 expressions (uv, dx, dy, s, layer, dref, cmp in scope)."""
    out = []
    for f in KINDS[kind]["forms"]:
        T, X = f["T"], f["X"]
        if f["manual"]:
            out += [f"tf_nearest({T}, uv{X}, s)", f"tf_bilinear({T}, uv{X}, s)",
                    f"tf_nearest_level({T}, uv{X}, 1, s.wrap)", f"tf_bilinear_level({T}, uv{X}, 1, s.wrap)",
                    f"tf_nearest_mip({T}, uv{X}, dx, dy, s)", f"tf_bilinear_mip({T}, uv{X}, dx, dy, s)",
                    f"tf_trilinear({T}, uv{X}, dx, dy, s)", f"tf_brilinear({T}, uv{X}, dx, dy, s, 0.25)",
                    f"tf_aniso({T}, uv{X}, dx, dy, s, 8, TF_ANISO_GPU)",
                    f"tf_ewa({T}, uv{X}, dx, dy, s, 2.0, 16.0)",
                    f"tf_fetch({T}, ivec2(uv * 16.0){X}, 0, s.wrap)"]
        if f["queries"]:
            out += [f"vec4(tf_lod({T}, dx, dy, s), tf_lod_unclamped({T}, dx, dy, 0.5), vec2(tf_level_size({T}, 1)))"]
        if f["hw"]:
            out += [f"tf_aniso_hw({T}, uv{X}, dx, dy, s, 8, TF_ANISO_FELINE)",
                    f"tf_ewa_hw({T}, uv{X}, dx, dy, s, 2.0, 16.0)"]
    for c in KINDS[kind].get("cube", []):
        T, X = c["T"], c["X"]
        d, dd = f"vec3(uv, 1.0 - uv.x){X}", "vec3(dx, 0.0), vec3(dy, 0.0)"
        # (the _mip forms are trilinear's two halves: compile_includes calls them)
        out += [f"tf_nearest_cube({T}, {d}, s)", f"tf_bilinear_cube({T}, {d}, s)",
                f"tf_trilinear_cube({T}, {d}, {dd}, s)", f"tf_aniso_cube({T}, {d}, {dd}, s, 8, TF_ANISO_GPU)",
                f"tf_aniso_cube_hw({T}, {d}, {dd}, s, 8, TF_ANISO_FELINE)", f"tf_ewa_cube({T}, {d}, {dd}, s, 2.0, 16.0)",
                f"tf_ewa_cube_hw({T}, {d}, {dd}, s, 2.0, 16.0)"]
    sat = KINDS[kind].get("sat")
    if sat:
        out += [f"tf_sat({sat['T']}, uv{sat['X']}, dx, dy, s, vec4(0.0), vec4(1.0))",
                f"tf_sat_assembly({sat['T']}, uv{sat['X']}, dx, dy, s, vec4(0.0), vec4(1.0), 4)"]
    return out


def shader(kind, stage, prelude="", bindless=False):
    """The test shader for KIND in STAGE; bindless: each texture an array of 8 indexed by nonuniformEXT(k)."""
    lines = ["#version 460", "#extension GL_GOOGLE_include_directive : require"]
    if stage == "rgen":
        lines.append("#extension GL_EXT_ray_tracing : require")
    if bindless:
        lines.append("#extension GL_EXT_nonuniform_qualifier : require")
    if kind == "source":
        prelude = SOURCE_PRELUDE + "\n" + prelude
    lines += [prelude, '#include "texfilter/texfilter.glsl"']
    expr = "".join(f"\n    r += {c};" for c in calls(kind))
    for binding, (type_, name) in enumerate(KINDS[kind]["textures"], start=8):
        if bindless and type_ not in SAMPLER_TYPES:
            lines.append(f"layout(set = 0, binding = {binding}) uniform {type_} {name}[8];")
            expr = re.sub(rf"\b{name}\b", f"{name}[nonuniformEXT(k)]", expr)
        else:
            lines.append(f"layout(set = 0, binding = {binding}) uniform {type_} {name};")
    # Every stage's inputs are divergent: k, layer and dref come from uv.
    body = """    int k = int(uv.x * 8.0) & 7, layer = int(uv.y * 4.0);
    float dref = uv.x;
    tf_Compare cmp = tf_compare(TF_COMPARE_LESS_OR_EQUAL, dref);
    tf_Sampler s = tf_sampler(TF_WRAP_REPEAT);"""
    if kind == "source":
        body += "\n    Tile src = Tile(ivec2(256 * k, 0), ivec2(200, 120), 8);"
    if stage == "frag":
        lines.append(f"""layout(location = 0) in vec2 uv;
layout(location = 0) out vec4 outColor;
void main()
{{
    vec2 dx = dFdxFine(uv), dy = dFdyFine(uv);
{body}
    vec4 r = vec4(0.0);{expr}
    outColor = r;
}}""")
    elif stage == "comp":
        lines.append(f"""layout(local_size_x = 64) in;
struct Lookup {{ vec2 uv, dUVdx, dUVdy; }};
layout(set = 0, binding = 1, std430) readonly buffer Lookups {{ Lookup lookups[]; }};
layout(set = 0, binding = 2, std430) writeonly buffer Colors {{ vec4 colors[]; }};
void main()
{{
    uint i = gl_GlobalInvocationID.x;
    vec2 uv = lookups[i].uv, dx = lookups[i].dUVdx, dy = lookups[i].dUVdy;
{body}
    vec4 r = vec4(0.0);{expr}
    colors[i] = r;
}}""")
    else:
        lines.append(f"""layout(set = 0, binding = 1) uniform accelerationStructureEXT topLevel;
layout(set = 0, binding = 2, rgba32f) uniform writeonly image2D colors;
struct Hit {{ vec2 uv, dUVdx, dUVdy; }};
layout(location = 0) rayPayloadEXT Hit hit;
void main()
{{
    ivec2 pixel = ivec2(gl_LaunchIDEXT.xy);
    vec2 ndc = 2.0 * (vec2(pixel) + 0.5) / vec2(gl_LaunchSizeEXT.xy) - 1.0;
    traceRayEXT(topLevel, gl_RayFlagsOpaqueEXT, 0xFF, 0, 0, 0, vec3(0.0), 0.0, normalize(vec3(ndc, 1.0)), 1e30, 0);
    vec2 uv = hit.uv, dx = hit.dUVdx, dy = hit.dUVdy;
{body}
    vec4 r = vec4(0.0);{expr}
    imageStore(colors, pixel, r);
}}""")
    return "\n".join(lines) + "\n"


class Tools:
    def __init__(self, glslang, glslc, spirv_dis, include_dir, work):
        self.glslang, self.glslc, self.spirv_dis, self.include_dir, self.work = glslang, glslc, spirv_dis, include_dir, work
        self.count = 0

    def compile(self, compiler, source, stage, optimise=False):
        """(ok, log, spv path) for SOURCE compiled as STAGE."""
        self.count += 1
        path = os.path.join(self.work, f"s{self.count}.{stage}")
        with open(path, "w") as f:
            f.write(source)
        spv = path + ".spv"
        if compiler == "glslangValidator":
            cmd = [self.glslang, "-V", "--target-env", "vulkan1.2", "-I" + self.include_dir, "-o", spv, path]
        else:
            cmd = [self.glslc, "--target-env=vulkan1.2", "-I", self.include_dir, "-Werror", "-o", spv, path]
        if optimise:
            cmd.insert(1, "-Os" if compiler == "glslangValidator" else "-O")
        r = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
        crash = f"{os.path.basename(cmd[0])} killed by signal {-r.returncode}\n" if r.returncode < 0 else ""
        return r.returncode == 0, crash + r.stdout, spv

    def disassemble(self, spv):
        return subprocess.run([self.spirv_dis, "--no-color", "--no-header", "--raw-id", spv], check=True,
                              stdout=subprocess.PIPE, text=True).stdout


def show_failure(log, source):
    print("      " + log.rstrip().replace("\n", "\n      "))
    print("      | " + source.rstrip().replace("\n", "\n      | "))


def run_compile(tools, kind, stage, compiler):
    source = shader(kind, stage)
    ok, log, _ = tools.compile(compiler, source, stage)
    print(f"{'ok  ' if ok else 'FAIL'}  {compiler} {stage} {kind}: {len(calls(kind))} calls")
    if not ok:
        show_failure(log, source)
    return ok


# glslang: "'tf_nearest' : no matching overloaded function found"; glslc reports the same text.
NO_OVERLOAD = re.compile(r"no matching overloaded function found")
ERROR_LINE = re.compile(r"^(ERROR: |.*: error: )(?!.*compilation (errors|terminated))(?!\d+ compilation)", re.M)


def run_resources(tools, kind):
    ok = True
    # The texel source: alone with TF_RESOURCES 0; "all but its kind" is every bit with TF_SOURCE left undefined.
    bit = BITS[KINDS[kind]["bit"]] if kind != "source" else 0
    others = ALL_BITS & ~bit
    for compiler in COMPILERS:
        only = shader(kind, "frag", f"#define TF_RESOURCES {bit}")
        good, log, _ = tools.compile(compiler, only, "frag")
        print(f"{'ok  ' if good else 'FAIL'}  {compiler} {kind} with TF_RESOURCES {bit} (its kind only) compiles")
        if not good:
            show_failure(log, only)
        without = shader(kind, "frag", f"#define TF_RESOURCES {others}")
        if kind == "source":
            without = without.replace("#define TF_SOURCE Tile\n", "")
        compiled, log, _ = tools.compile(compiler, without, "frag")
        errors = [l for l in log.splitlines() if re.search(r"\berror\b|^ERROR:", l)
                  and not re.search(r"compilation (errors|terminated)|^\d+ errors? generated|error\(s\)", l)]
        wrong = [l for l in errors if not NO_OVERLOAD.search(l)]
        fails_right = not compiled and errors and not wrong
        print(f"{'ok  ' if fails_right else 'FAIL'}  {compiler} {kind} with TF_RESOURCES {others} (all but its kind) "
              f"fails: {len(errors)} error(s), each 'no matching overloaded function'")
        if not fails_right:
            print("      " + ("it compiled" if compiled else "other errors:\n      " + "\n      ".join(wrong or errors)))
        ok = ok and good and fails_right
    return ok


IMAGE_OPS = re.compile(r"^OpImage(Sample|Fetch|Gather|DrefGather|Query|Read|Sparse)")


def parse(dis):
    """(definitions id -> (opcode, operand tokens), NonUniform ids, image instructions [(opcode, image id)])."""
    defs, nonuniform, uses = {}, set(), []
    for line in dis.splitlines():
        tokens = line.split()
        if not tokens:
            continue
        if tokens[0] == "OpDecorate" and len(tokens) >= 3 and tokens[2] in ("NonUniform", "NonUniformEXT"):
            nonuniform.add(tokens[1])
        elif len(tokens) >= 3 and tokens[1] == "=":
            result, opcode, operands = tokens[0], tokens[2], tokens[3:]
            defs[result] = (opcode, operands)
            if IMAGE_OPS.match(opcode):
                uses.append((opcode, operands[1]))  # operands[0] is the result type
    return defs, nonuniform, uses


# The rule (Vulkan spec, "Shader Interfaces": when the descriptor a resource access goes through is not
# dynamically uniform, the operand that selects the resource must be decorated NonUniform; decorating the
# index alone does not carry over to the loaded resource): every image instruction (OpImageSample*,
# OpImageFetch, OpImageGather, OpImageDrefGather, OpImageQuery*, OpImageRead, OpImageSparse*) takes as its
# Image / Sampled Image operand an id decorated NonUniform. Where that id is made by OpImage (the image of
# a sampled image) or OpSampledImage (an image and a sampler combined: sampler2D(tex, smp)), the image it
# is made from must be NonUniform too, and so on back; the chain ends at the OpLoad of the descriptor or
# the OpCopyObject that nonuniformEXT(...) makes, which must itself be decorated. (The sampler side of
# OpSampledImage is one uniform descriptor in these shaders, not followed.)
FOLLOW = {"OpImage": 1, "OpSampledImage": 1}  # operand index (after the result type) of the image it comes from


def undecorated(defs, nonuniform, image_id):
    """The first id on IMAGE_ID's chain that lacks NonUniform, or None."""
    current, seen = image_id, set()
    while current not in seen:
        seen.add(current)
        if current not in nonuniform:
            return current
        opcode, operands = defs.get(current, ("", []))
        if opcode not in FOLLOW:
            return None
        current = operands[FOLLOW[opcode]]
    return None


def check_nonuniform(tools, kind, compiler, optimise, with_hook):
    # Only the kind's own instantiation (TF_RESOURCES): what is checked is the decoration of its calls, and
    # the -O compiles of every kind at once were most of the suite's time here (compile.* covers all kinds).
    prelude = f"#define TF_RESOURCES {BITS[KINDS[kind]['bit']]}\n"
    prelude += "#define TF_NONUNIFORM nonuniformEXT" if with_hook else ""
    source = shader(kind, "comp", prelude, bindless=True)
    ok, log, spv = tools.compile(compiler, source, "comp", optimise)
    label = f"{compiler}{' -O' if optimise else ''} {kind} {'with' if with_hook else 'without'} TF_NONUNIFORM"
    if not ok:
        print(f"FAIL  {label}: does not compile")
        show_failure(log, source)
        return None
    defs, nonuniform, uses = parse(tools.disassemble(spv))
    bad = [(op, img, undecorated(defs, nonuniform, img)) for op, img in uses]
    bad = [b for b in bad if b[2] is not None]
    return label, len(uses), bad


def run_nonuniform(tools, kind):
    ok = True
    for compiler in COMPILERS:
        # Optimised once, with glslc -O (shaderc's pass list, what engines ship with); glslangValidator -Os
        # runs the same SPIRV-Tools optimiser and cost the suite a fifth of these tests' time.
        for optimise in ((False, True) if compiler == "glslc" else (False,)):
            r = check_nonuniform(tools, kind, compiler, optimise, True)
            if r is None:
                ok = False
                continue
            label, n, bad = r
            good = n > 0 and not bad
            print(f"{'ok  ' if good else 'FAIL'}  {label}: {n} image instructions, {len(bad)} without NonUniform")
            for op, img, where in bad[:10]:
                print(f"      {op} on {img}: {where} is not decorated NonUniform")
            ok = ok and good
        # The negative: without the hook the includes' own image operands are plain (calls not inlined).
        r = check_nonuniform(tools, kind, compiler, False, False)
        if r is None:
            ok = False
            continue
        label, n, bad = r
        good = len(bad) > 0
        print(f"{'ok  ' if good else 'FAIL'}  {label}: {len(bad)} of {n} image instructions without NonUniform "
              f"(the check can fail)")
        ok = ok and good
    return ok


def groups():
    out = [f"compile.{k}.{s}.{c}" for k in KINDS for s in KINDS[k].get("stages", STAGES) for c in COMPILERS]
    out += [f"resources.{k}" for k in KINDS]
    out += [f"nonuniform.{k}" for k in KINDS if k != "source"]  # a source's fetch is the user's code
    return out


def main(argv):
    if argv[1:] == ["--list"]:
        print("\n".join(groups()))
        return 0
    if len(argv) != 6 or argv[5] not in groups():
        print(__doc__, file=sys.stderr)
        return 2
    group = argv[5].split(".")
    with tempfile.TemporaryDirectory() as work:
        tools = Tools(argv[1], argv[2], argv[3], argv[4], work)
        if group[0] == "compile":
            ok = run_compile(tools, group[1], group[2], group[3])
        elif group[0] == "resources":
            ok = run_resources(tools, group[1])
        else:
            ok = run_nonuniform(tools, group[1])
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main(sys.argv))
