// PrismLiveDraw: the drawing and measuring pieces of the gallery report's live views
// (gallery_live.js and live_bluenoise.js, docs/web.md): the page's one WebGL2 context, meshes
// from base64 data, a draw with a program that prism_web.js built, the exact view of a PNG
// drawn off-screen and read back top row first, the PNG decoded into a canvas, and the
// agreement figures. A plain script.
var PrismLiveDraw = (function () {
  "use strict";

  function decode(base64, Type) {
    var bytes = Uint8Array.from(atob(base64), function (c) { return c.charCodeAt(0); });
    return new Type(bytes.buffer);
  }

  // ---- matrices (column-major, as GL reads them) ----
  function mul4(a, b) {
    var r = new Float32Array(16);
    for (var c = 0; c < 4; ++c)
      for (var row = 0; row < 4; ++row)
        for (var k = 0; k < 4; ++k) r[4 * c + row] += a[4 * k + row] * b[4 * c + k];
    return r;
  }
  function rotation(angleX, angleY) {
    var cx = Math.cos(angleX), sx = Math.sin(angleX), cy = Math.cos(angleY), sy = Math.sin(angleY);
    var rx = [1, 0, 0, 0, 0, cx, sx, 0, 0, -sx, cx, 0, 0, 0, 0, 1];
    var ry = [cy, 0, -sy, 0, 0, 1, 0, 0, sy, 0, cy, 0, 0, 0, 0, 1];
    return mul4(rx, ry);
  }
  // The inverse transpose of the upper 3x3 of `m` (the eye-space normal matrix).
  function normalMatrix(m) {
    var a = [m[0], m[1], m[2], m[4], m[5], m[6], m[8], m[9], m[10]];
    var c00 = a[4] * a[8] - a[5] * a[7], c01 = a[5] * a[6] - a[3] * a[8], c02 = a[3] * a[7] - a[4] * a[6];
    var c10 = a[2] * a[7] - a[1] * a[8], c11 = a[0] * a[8] - a[2] * a[6], c12 = a[1] * a[6] - a[0] * a[7];
    var c20 = a[1] * a[5] - a[2] * a[4], c21 = a[2] * a[3] - a[0] * a[5], c22 = a[0] * a[4] - a[1] * a[3];
    var det = a[0] * c00 + a[1] * c01 + a[2] * c02;
    return [c00, c01, c02, c10, c11, c12, c20, c21, c22].map(function (x) { return x / det; });
  }

  // ---- drawing ----
  function uploadMesh(gl, mesh) {
    var vao = gl.createVertexArray();
    gl.bindVertexArray(vao);
    [["positions", 0], ["normals", 1]].forEach(function (p) {
      var buffer = gl.createBuffer();
      gl.bindBuffer(gl.ARRAY_BUFFER, buffer);
      gl.bufferData(gl.ARRAY_BUFFER, decode(mesh[p[0]], Float32Array), gl.STATIC_DRAW);
      gl.enableVertexAttribArray(p[1]);
      gl.vertexAttribPointer(p[1], 3, gl.FLOAT, false, 12, 0);
    });
    var indices = decode(mesh.indices, Uint32Array);
    gl.bindBuffer(gl.ELEMENT_ARRAY_BUFFER, gl.createBuffer());
    gl.bufferData(gl.ELEMENT_ARRAY_BUFFER, indices, gl.STATIC_DRAW);
    gl.bindVertexArray(null);
    return {vao: vao, count: indices.length};
  }

  // Draws `mesh` with program `built` and the uniform values `uniforms` into the bound framebuffer.
  function draw(gl, built, mesh, uniforms, background, width, height) {
    gl.viewport(0, 0, width, height);
    gl.clearColor(background[0], background[1], background[2], background[3]);
    gl.clear(gl.COLOR_BUFFER_BIT | gl.DEPTH_BUFFER_BIT);
    gl.enable(gl.DEPTH_TEST);
    gl.depthFunc(gl.LESS);
    gl.disable(gl.CULL_FACE);
    gl.disable(gl.BLEND);
    gl.useProgram(built.program);
    Object.keys(uniforms).forEach(function (name) { PrismWeb.setUniform(gl, built, name, uniforms[name]); });
    gl.bindVertexArray(mesh.vao);
    gl.drawElements(gl.TRIANGLES, mesh.count, gl.UNSIGNED_INT, 0);
    gl.bindVertexArray(null);
  }

  // The pixels of what is bound, top row first (as a PNG stores them).
  function readTopDown(gl, width, height) {
    var raw = new Uint8Array(width * height * 4), out = new Uint8Array(width * height * 4);
    gl.readPixels(0, 0, width, height, gl.RGBA, gl.UNSIGNED_BYTE, raw);
    for (var y = 0; y < height; ++y) out.set(raw.subarray((height - 1 - y) * width * 4, (height - y) * width * 4), y * width * 4);
    return out;
  }

  // Runs `drawInto(width, height)` with an RGBA8 framebuffer (and a depth buffer) bound and
  // returns its pixels, top row first.
  function offscreen(gl, width, height, drawInto) {
    var fb = gl.createFramebuffer(), colour = gl.createRenderbuffer(), depth = gl.createRenderbuffer();
    gl.bindRenderbuffer(gl.RENDERBUFFER, colour);
    gl.renderbufferStorage(gl.RENDERBUFFER, gl.RGBA8, width, height);
    gl.bindRenderbuffer(gl.RENDERBUFFER, depth);
    gl.renderbufferStorage(gl.RENDERBUFFER, gl.DEPTH_COMPONENT24, width, height);
    gl.bindFramebuffer(gl.FRAMEBUFFER, fb);
    gl.framebufferRenderbuffer(gl.FRAMEBUFFER, gl.COLOR_ATTACHMENT0, gl.RENDERBUFFER, colour);
    gl.framebufferRenderbuffer(gl.FRAMEBUFFER, gl.DEPTH_ATTACHMENT, gl.RENDERBUFFER, depth);
    drawInto(width, height);
    var pixels = readTopDown(gl, width, height);
    gl.bindFramebuffer(gl.FRAMEBUFFER, null);
    gl.deleteFramebuffer(fb);
    [colour, depth].forEach(gl.deleteRenderbuffer, gl);
    return pixels;
  }

  // Draws the exact view of `record` off-screen and returns its pixels, top row first.
  function drawExact(gl, built, mesh, record) {
    return offscreen(gl, record.width, record.height, function (w, h) {
      draw(gl, built, mesh, record.uniforms, record.background, w, h);
    });
  }

  // One WebGL2 context for every live view of the page (a context is costly to make, and the
  // browser caps how many live at once), drawing into an off-screen canvas; null without WebGL2.
  var shared;
  function sharedContext() {
    if (shared === undefined) {
      var canvas = document.createElement("canvas");
      var gl = canvas.getContext("webgl2", {antialias: false, preserveDrawingBuffer: true});
      shared = gl ? {canvas: canvas, gl: gl} : null;
    }
    return shared;
  }

  // Largest channel difference (in 1/255), mean difference (in 1/255) and the share of pixels
  // within 2/255 in every channel, over RGB.
  function agreement(a, b) {
    var max = 0, sum = 0, within = 0, n = a.length / 4;
    for (var i = 0; i < a.length; i += 4) {
      var worst = 0;
      for (var c = 0; c < 3; ++c) {
        var d = Math.abs(a[i + c] - b[i + c]);
        sum += d;
        if (d > worst) worst = d;
      }
      if (worst > max) max = worst;
      if (worst <= 2) ++within;
    }
    return {max: max, mean: sum / (3 * n), within: within / n};
  }

  // A view that has no PNG to compare with: no figures, state "no-reference", `why` shown.
  function noReference(figure, info, why) {
    ["png", "max", "mean", "within"].forEach(function (k) { figure.removeAttribute("data-agreement-" + k); });
    figure.setAttribute("data-agreement-state", "no-reference");
    info.textContent = why;
  }

  // Decodes the PNG `png` (data: URI `uri`, drawn by `source`), compares it with `pixels` (top
  // row first) and writes the figures into the view's element (data-agreement-*) and `info`;
  // a result for which `current()` is false (the controls moved on meanwhile) is dropped.
  function compareWithPng(figure, info, png, uri, source, pixels, current) {
    figure.setAttribute("data-agreement-state", "pending");
    decodePng(uri, function (decoded) {
      if (!current()) return;
      if (!decoded || decoded.length !== pixels.length) {
        figure.setAttribute("data-agreement-state", "error");
        info.textContent = "cannot decode " + png;
        return;
      }
      var a = agreement(pixels, decoded);
      figure.setAttribute("data-agreement-png", png);
      figure.setAttribute("data-agreement-max", a.max);
      figure.setAttribute("data-agreement-mean", a.mean.toFixed(4));
      figure.setAttribute("data-agreement-within", a.within.toFixed(5));
      figure.setAttribute("data-agreement-state", "done");
      info.textContent = "against " + png + " (" + source + "): max " + a.max + "/255, mean " + a.mean.toFixed(3) +
                         "/255, " + (100 * a.within).toFixed(2) + " % of pixels within 2/255";
    });
  }

  function decodePng(uri, done) {
    var img = new Image();
    img.onload = function () {
      var canvas = document.createElement("canvas");
      canvas.width = img.naturalWidth;
      canvas.height = img.naturalHeight;
      var ctx = canvas.getContext("2d");
      ctx.drawImage(img, 0, 0);
      done(ctx.getImageData(0, 0, canvas.width, canvas.height).data);
    };
    img.onerror = function () { done(null); };
    img.src = uri;
  }

  // Distinct colours, the share of pixels off the background and a checksum of `pixels`.
  function pictureStats(pixels, background) {
    var colours = {}, count = 0, covered = 0, hash = 2166136261;
    var bg = background.map(function (x) { return Math.round(x * 255); });
    for (var i = 0; i < pixels.length; i += 4) {
      var key = (pixels[i] << 16) | (pixels[i + 1] << 8) | pixels[i + 2];
      if (!colours[key]) { colours[key] = 1; ++count; }
      if (Math.abs(pixels[i] - bg[0]) + Math.abs(pixels[i + 1] - bg[1]) + Math.abs(pixels[i + 2] - bg[2]) > 6) ++covered;
      hash = Math.imul(hash ^ key, 16777619) >>> 0;
    }
    return {colours: count, covered: covered / (pixels.length / 4), checksum: hash.toString(16)};
  }

  return {mul4: mul4, rotation: rotation, normalMatrix: normalMatrix, uploadMesh: uploadMesh, draw: draw,
          offscreen: offscreen, drawExact: drawExact, sharedContext: sharedContext, agreement: agreement,
          noReference: noReference, compareWithPng: compareWithPng, decodePng: decodePng, pictureStats: pictureStats,
          readTopDown: readTopDown};
})();
