// The gallery report's live blue-noise soft-shadow view (docs/web.md): the GPU soft-shadow
// shader of the blue-noise catalogue (PrismWebCatalogs["prism::bluenoise_shaders"],
// soft_shadows.{vert,frag}) drawn through WebGL2 with the mask and uniforms that
// `prism-bluenoise render --live-record` wrote beside the main job's PNGs
// (PrismGalleryLive.bluenoise, from scripts/gallery_live.py). Controls: blue-noise mask or
// white noise, samples per pixel, frame and light length. In the state of a PNG (1 spp,
// frame 0, the scene's light) the picture is that PNG's exact frame, and the view writes its
// agreement into data-agreement-* attributes, as the classic views do (gallery_live.js).
// A plain script: works from file://.
(function () {
  "use strict";
  var data = window.PrismGalleryLive && window.PrismGalleryLive.bluenoise, D = window.PrismLiveDraw;
  var catalogue = data && (window.PrismWebCatalogs || {})[data.catalogue];
  var section = document.getElementById("live"), context = D && D.sharedContext();
  if (!data || !catalogue || !section || !context) return;  // gallery_live.js says why when WebGL2 is missing
  var gl = context.gl;
  var SAMPLERS = {white: 0, bluenoise: 1};  // u_blueNoiseSampler (modules/bluenoise/sampling.glsl)

  function element(tag, attrs, parent) {
    var e = document.createElement(tag);
    Object.keys(attrs).forEach(function (k) { e.setAttribute(k, attrs[k]); });
    parent.appendChild(e);
    return e;
  }

  // An R32UI texture on `unit` (integer textures take nearest filtering only).
  function uintTexture(unit, width, height, values) {
    var texture = gl.createTexture();
    gl.activeTexture(gl.TEXTURE0 + unit);
    gl.bindTexture(gl.TEXTURE_2D, texture);
    gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MIN_FILTER, gl.NEAREST);
    gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MAG_FILTER, gl.NEAREST);
    gl.texImage2D(gl.TEXTURE_2D, 0, gl.R32UI, width, height, 0, gl.RED_INTEGER, gl.UNSIGNED_INT, values);
    return texture;
  }

  // The textures of sampling.glsl, as GlSoftShadows binds them for the white and bluenoise
  // samplers: the mask on unit 0, the unused seeds and stack (1x1, 0) on units 1 and 2.
  var mask = data.mask, values = new Uint32Array(Uint8Array.from(atob(mask.values), function (c) {
    return c.charCodeAt(0);
  }).buffer);
  var textures = [uintTexture(0, mask.width, mask.height, values), uintTexture(1, 1, 1, new Uint32Array(1)),
                  uintTexture(2, 1, 1, new Uint32Array(1))];
  var built = PrismWeb.build(gl, catalogue, data.program, {});
  var vao = gl.createVertexArray();  // the full-screen triangle comes from gl_VertexID

  // Draws one frame with `uniforms` and returns it as the grey PNG stores it: the shader writes
  // the irradiance to red (clamped to [0, 1] by the RGBA8 target, as the PNG clamps it).
  function drawFrame(uniforms) {
    var pixels = D.offscreen(gl, uniforms.u_imageSize[0], uniforms.u_imageSize[1], function (w, h) {
      gl.viewport(0, 0, w, h);
      [gl.DEPTH_TEST, gl.CULL_FACE, gl.BLEND].forEach(gl.disable, gl);
      gl.useProgram(built.program);
      Object.keys(uniforms).forEach(function (name) { PrismWeb.setUniform(gl, built, name, uniforms[name]); });
      textures.forEach(function (t, unit) { gl.activeTexture(gl.TEXTURE0 + unit); gl.bindTexture(gl.TEXTURE_2D, t); });
      gl.bindVertexArray(vao);
      gl.drawArrays(gl.TRIANGLES, 0, 3);
      gl.bindVertexArray(null);
    });
    for (var i = 0; i < pixels.length; i += 4) pixels[i + 1] = pixels[i + 2] = pixels[i];
    return pixels;
  }

  function samplerOf(record) {
    return Object.keys(SAMPLERS).filter(function (k) { return SAMPLERS[k] === record.uniforms.u_blueNoiseSampler[0]; })[0];
  }
  // The same uniform values as the shader gets them (the record's floats went through JSON).
  function sameUniforms(a, b) {
    var ka = Object.keys(a).sort(), kb = Object.keys(b).sort();
    return JSON.stringify(ka) === JSON.stringify(kb) && ka.every(function (k) {
      return a[k].length === b[k].length && a[k].every(function (x, i) { return Math.fround(x) === Math.fround(b[k][i]); });
    });
  }

  function SoftShadowView(figure, canvas, info) {
    var records = data.views, first = records.filter(function (r) { return samplerOf(r) === "bluenoise"; })[0] || records[0];
    var state = {sampler: samplerOf(first), spp: 1, frame: 0, halfLength: first.uniforms.u_light[1]};

    // The record of this state's sampler, or null, and the uniforms of the state.
    function recordOf() { return records.filter(function (r) { return samplerOf(r) === state.sampler; })[0] || null; }
    function uniformsOf() {
      var u = Object.assign({}, (recordOf() || first).uniforms);
      u.u_blueNoiseSampler = [SAMPLERS[state.sampler]];
      u.u_spp = [state.spp];
      u.u_frame = [state.frame];
      u.u_light = [u.u_light[0], state.halfLength, u.u_light[2], u.u_light[3]];
      return u;
    }

    function describe(pixels) {
      var stats = D.pictureStats(pixels, [0, 0, 0, 1]);
      figure.setAttribute("data-live-variant", "sampler=" + state.sampler + ",spp=" + state.spp + ",frame=" +
                          state.frame + ",halfLength=" + state.halfLength);
      figure.setAttribute("data-live-colours", stats.colours);
      figure.setAttribute("data-live-covered", stats.covered.toFixed(4));
      figure.setAttribute("data-live-checksum", stats.checksum);
      figure.setAttribute("data-live-float-precision", PrismWeb.floatPrecision(catalogue.texts[built.variant.stages.frag]));
    }

    // Compares `pixels` with the record's PNG when the state is exactly the record's frame.
    function measure(pixels, uniforms) {
      var record = recordOf();
      if (!record || !sameUniforms(uniforms, record.uniforms))
        return D.noReference(figure, info, "no PNG of this state to compare with (the main job's are 1 spp, frame 0, " +
                                           "the scene's light)");
      D.compareWithPng(figure, info, record.png, data.pngs[record.png], "prism-bluenoise, CPU", pixels, function () {
        return sameUniforms(uniformsOf(), uniforms);
      });
    }

    this.update = function () {
      try {
        var uniforms = uniformsOf(), pixels = drawFrame(uniforms);
        var image = new ImageData(new Uint8ClampedArray(pixels.buffer), uniforms.u_imageSize[0], uniforms.u_imageSize[1]);
        canvas.getContext("2d").putImageData(image, 0, 0);
        describe(pixels);
        measure(pixels, uniforms);
        figure.removeAttribute("data-live-error");
      } catch (e) {
        figure.setAttribute("data-live-error", e.message);
        info.textContent = "error: " + e.message;
      }
    };
    this.state = state;
  }

  // One labelled control that sets state[key] from the input and redraws.
  function control(box, view, label, attrs, read) {
    var wrap = element("label", {}, box);
    wrap.appendChild(document.createTextNode(label + " "));
    var input = element("input", attrs, wrap);
    input.addEventListener(attrs.type === "checkbox" ? "change" : "input", function () { read(input); view.update(); });
    return input;
  }

  var record = data.views[0];
  var figure = element("figure", {"class": "live-view", id: "live-soft_shadows", "data-shader": "soft_shadows"}, section);
  var canvas = element("canvas", {width: record.width, height: record.height, "class": "live-canvas"}, figure);
  element("figcaption", {}, figure).textContent =
      "blue-noise soft shadows (WebGL2; the GPU shader of docs/bluenoise.md, one frame)";
  var info = element("div", {"class": "agreement"}, figure);
  var view = new SoftShadowView(figure, canvas, info), s = view.state;
  var box = element("div", {"class": "live-controls"}, figure);
  control(box, view, "blue-noise mask (off: white noise)", {type: "checkbox", "data-axis": "u_blueNoiseSampler"},
          function (i) { s.sampler = i.checked ? "bluenoise" : "white"; }).checked = s.sampler === "bluenoise";
  control(box, view, "samples per pixel", {type: "range", min: 1, max: 16, value: s.spp}, function (i) { s.spp = +i.value; });
  control(box, view, "frame", {type: "range", min: 0, max: 63, value: s.frame}, function (i) { s.frame = +i.value; });
  control(box, view, "light length", {type: "range", min: 0.05, max: 1.5, step: 0.05, value: s.halfLength},
          function (i) { s.halfLength = +i.value; });
  view.update();
})();
