// PrismWeb: builds WebGL2 programs from a Prism web catalogue (prism-shaderc --emit-web;
// docs/web.md). A plain script, no module syntax, so a page opened from file:// can load it:
//
//   <script src="prism_shaders.js"></script>  <!-- defines PrismWebCatalogs["prism::shaders"] -->
//   <script src="prism_web.js"></script>
//   var catalogue = PrismWebCatalogs["prism::shaders"];
//   var built = PrismWeb.build(gl, catalogue, "phong", {BLINN: "1"});  // the first variant with BLINN=1
//   gl.useProgram(built.program);
//   PrismWeb.setUniform(gl, built, "u_color", [0.85, 0.42, 0.25, 1]);
//
// Attributes are bound at the locations the catalogue's reflection gives (the binding
// contract's), and uniforms are set by name with the setter their reflected type needs.
var PrismWeb = (function () {
  "use strict";

  // The variants of `program` whose defines agree with every value `wanted` gives.
  function matchingVariants(program, wanted) {
    return program.variants.filter(function (v) {
      return Object.keys(wanted).every(function (axis) { return v.defines[axis] === String(wanted[axis]); });
    });
  }

  function findVariant(program, wanted) {
    var found = matchingVariants(program, wanted);
    return found.length ? found[0] : null;
  }

  function compileStage(gl, type, text, label) {
    var shader = gl.createShader(type);
    gl.shaderSource(shader, text);
    gl.compileShader(shader);
    if (!gl.getShaderParameter(shader, gl.COMPILE_STATUS))
      throw new Error(label + ": " + gl.getShaderInfoLog(shader));
    return shader;
  }

  // {program, variant, uniforms: name -> {location, type}} for `name` with the defines `wanted`.
  function build(gl, catalogue, name, wanted) {
    var entry = catalogue.programs[name];
    if (!entry) throw new Error("no program '" + name + "' in web catalogue " + catalogue.name);
    var variant = findVariant(entry, wanted || {});
    if (!variant) throw new Error("program '" + name + "' has no variant with " + JSON.stringify(wanted));
    var label = catalogue.name + " " + name + " " + variant.name;
    var program = gl.createProgram();
    gl.attachShader(program, compileStage(gl, gl.VERTEX_SHADER, catalogue.texts[variant.stages.vert], label + " vert"));
    gl.attachShader(program, compileStage(gl, gl.FRAGMENT_SHADER, catalogue.texts[variant.stages.frag], label + " frag"));
    variant.attributes.forEach(function (a) { if (a.location >= 0) gl.bindAttribLocation(program, a.location, a.name); });
    gl.linkProgram(program);
    if (!gl.getProgramParameter(program, gl.LINK_STATUS)) throw new Error(label + ": " + gl.getProgramInfoLog(program));
    var uniforms = {};
    variant.uniforms.forEach(function (u) {  // by name, and an array's elements also as "name[i]"
      uniforms[u.name] = {location: gl.getUniformLocation(program, u.name), type: u.type};
      for (var i = 0; i < u.size; ++i) {
        var location = gl.getUniformLocation(program, u.name + "[" + i + "]");
        if (location !== null) uniforms[u.name + "[" + i + "]"] = {location: location, type: u.type};
      }
    });
    return {program: program, variant: variant, uniforms: uniforms};
  }

  // Sets uniform `name` (an array element as "u_lightColor[1]") of the bound program `built`;
  // false when the variant has no such uniform.
  function setUniform(gl, built, name, value) {
    var u = built.uniforms[name];
    if (!u || u.location === null) return false;
    var v = Array.isArray(value) || ArrayBuffer.isView(value) ? value : [value];
    switch (u.type) {
      case "float": gl.uniform1fv(u.location, v); break;
      case "vec2": gl.uniform2fv(u.location, v); break;
      case "vec3": gl.uniform3fv(u.location, v); break;
      case "vec4": gl.uniform4fv(u.location, v); break;
      case "mat3": gl.uniformMatrix3fv(u.location, false, v); break;
      case "mat4": gl.uniformMatrix4fv(u.location, false, v); break;
      case "ivec2": gl.uniform2iv(u.location, v); break;
      case "ivec3": gl.uniform3iv(u.location, v); break;
      case "ivec4": gl.uniform4iv(u.location, v); break;
      case "uint": gl.uniform1uiv(u.location, v); break;
      case "uvec2": gl.uniform2uiv(u.location, v); break;
      case "uvec3": gl.uniform3uiv(u.location, v); break;
      case "uvec4": gl.uniform4uiv(u.location, v); break;
      default: gl.uniform1iv(u.location, v.map(function (x) { return Math.round(x); }));  // int, bool, samplers
    }
    return true;
  }

  // The default float precision a stage text ends up with: its last `precision X float;`
  // (Prism's es300 texts say highp; a module may ask for mediump). Pixels cannot tell: a
  // browser on SwiftShader, as on most desktop GPUs, runs mediump at 32 bits.
  function floatPrecision(text) {
    var found = null, re = /precision\s+(lowp|mediump|highp)\s+float\s*;/g, m;
    while ((m = re.exec(text)) !== null) found = m[1];
    return found;
  }

  return {matchingVariants: matchingVariants, findVariant: findVariant, build: build, setUniform: setUniform,
          floatPrecision: floatPrecision};
})();
