// The gallery report's live views (docs/web.md): each classic catalogue shader drawn through
// WebGL2 from the web catalogue (PrismWebCatalogs, built with prism_web.js) on the gallery's
// meshes (PrismGalleryLive, written by scripts/gallery_live.py from prism-gallery's
// live-views.json), with controls for its variant axes (combinations the catalogue lacks
// greyed out), light direction, shininess, specular, colour and mouse rotation. Each view
// also draws the exact view of its llvmpipe PNG, compares the two and writes the figures into
// data-agreement-* attributes (drawing: live_draw.js). A plain script: works from file://.
(function () {
  "use strict";
  var data = window.PrismGalleryLive, D = window.PrismLiveDraw;
  var catalogue = data && (window.PrismWebCatalogs || {})[data.catalogue];
  var section = document.getElementById("live");
  var status = document.getElementById("live-status");
  if (!data || !catalogue || !section) return;
  if (location.hash === "#live-only") document.body.classList.add("live-only");  // for a screenshot of the views

  function meshName(key) { return key.split(".")[0]; }
  function sameDefines(a, b) {
    var ka = Object.keys(a), kb = Object.keys(b);
    return ka.length === kb.length && ka.every(function (k) { return a[k] === b[k]; });
  }
  function viewsOf(shader) { return data.views.filter(function (r) { return r.shader === shader; }); }

  // The record of the PNG for exactly this state, or null.
  function exactRecord(state) {
    return viewsOf(state.shader).filter(function (r) {
      return meshName(r.mesh) === state.mesh && sameDefines(r.defines, state.defines);
    })[0] || null;
  }
  // The record whose uniforms the interactive picture starts from: the exact one, else the one
  // on the same mesh sharing the most axis values.
  function baseRecord(state) {
    var best = null, bestScore = -1;
    viewsOf(state.shader).forEach(function (r) {
      if (meshName(r.mesh) !== state.mesh) return;
      var score = Object.keys(r.defines).filter(function (k) { return r.defines[k] === state.defines[k]; }).length;
      if (score > bestScore) { best = r; bestScore = score; }
    });
    return best;
  }

  function hexColour(rgb) {
    return "#" + rgb.slice(0, 3).map(function (x) { return ("0" + Math.round(x * 255).toString(16)).slice(-2); }).join("");
  }

  function element(tag, attrs, parent) {
    var e = document.createElement(tag);
    Object.keys(attrs || {}).forEach(function (k) { e.setAttribute(k, attrs[k]); });
    if (parent) parent.appendChild(e);
    return e;
  }

  // One labelled control; `onInput` reads it back.
  function control(box, label, attrs, onInput) {
    var wrap = element("label", {}, box);
    wrap.appendChild(document.createTextNode(label + " "));
    var input = element(attrs.tag || "input", attrs.tag ? {} : attrs, wrap);
    input.addEventListener(attrs.type === "checkbox" || attrs.tag === "select" ? "change" : "input", onInput);
    return input;
  }

  // One WebGL2 context draws every view (a context is costly to make, and meshes and programs
  // are then uploaded and compiled once); each view shows its picture in a 2D canvas of its own.
  var context = D.sharedContext(), glCanvas = context && context.canvas, gl = context && context.gl;
  var meshes = {}, programs = {}, loading = {};

  // Runs `then` once mesh `name`'s file (live/mesh-<name>.js: its meshes and PNGs) has loaded.
  function withMesh(name, then) {
    if (data.loaded[name]) return then();
    if (!loading[name]) {
      loading[name] = [];
      var script = document.createElement("script");
      script.src = "live/" + data.meshFiles[name];
      script.onload = function () { loading[name].forEach(function (f) { f(); }); };
      document.head.appendChild(script);
    }
    loading[name].push(then);
  }
  data.addMesh = function (name, part) {
    Object.assign(data.meshes, part.meshes);
    Object.assign(data.pngs, part.pngs);
    data.loaded[name] = true;
  };

  function LiveView(shader, canvas, figure) {
    var program = catalogue.programs[shader];
    var ctx2d = canvas.getContext("2d");
    var first = viewsOf(shader).filter(function (r) { return meshName(r.mesh) === data.defaultMesh; })[0] ||
                viewsOf(shader)[0];
    var state = {shader: shader, mesh: meshName(first.mesh), defines: Object.assign({}, first.defines),
                 angleX: 0, angleY: 0, overrides: {}};
    var axisInputs = {};
    var info = element("div", {"class": "agreement"}, figure);

    function meshOf(record) {
      if (!meshes[record.mesh]) meshes[record.mesh] = D.uploadMesh(gl, data.meshes[record.mesh]);
      return meshes[record.mesh];
    }
    function builtFor(defines) {
      var key = shader + JSON.stringify(defines);
      if (!programs[key]) programs[key] = PrismWeb.build(gl, catalogue, shader, defines);
      return programs[key];
    }

    // The interactive picture: the base record's uniforms with the controls' changes on top.
    function interactiveUniforms(record, built) {
      var u = Object.assign({}, record.uniforms, state.overrides);
      var spin = D.rotation(state.angleX, state.angleY);
      u.u_world = D.mul4(spin, record.uniforms.u_world);
      u.u_normal = D.normalMatrix(D.mul4(record.uniforms.u_view, u.u_world));
      [["u_directionalLightCount", "u_lightDirection"], ["u_pointLightCount", "u_pointLightPosition"]].forEach(function (p) {
        var capacity = built.variant.uniforms.filter(function (x) { return x.name === p[1]; }).map(function (x) { return x.size; })[0] || 0;
        if (u[p[0]]) u[p[0]] = [Math.min(u[p[0]][0], capacity)];
      });
      return u;
    }

    // `quick` (while dragging) leaves out the read-back for the data-live-* figures.
    function drawInteractive(quick) {
      var record = baseRecord(state), built = builtFor(state.defines);
      glCanvas.width = canvas.width;
      glCanvas.height = canvas.height;
      gl.bindFramebuffer(gl.FRAMEBUFFER, null);
      D.draw(gl, built, meshOf(record), interactiveUniforms(record, built), record.background, canvas.width, canvas.height);
      ctx2d.drawImage(glCanvas, 0, 0);
      if (quick) return;
      var stats = D.pictureStats(D.readTopDown(gl, canvas.width, canvas.height), record.background);
      figure.setAttribute("data-live-variant", built.variant.name);
      figure.setAttribute("data-live-colours", stats.colours);
      figure.setAttribute("data-live-covered", stats.covered.toFixed(4));
      figure.setAttribute("data-live-checksum", stats.checksum);
      figure.setAttribute("data-live-float-precision", PrismWeb.floatPrecision(catalogue.texts[built.variant.stages.frag]));
    }

    function measure() {
      var record = exactRecord(state);
      if (!record || !data.pngs[record.png])
        return D.noReference(figure, info, "no llvmpipe PNG of this combination to compare with");
      var pixels = D.drawExact(gl, builtFor(record.defines), meshOf(record), record);
      D.compareWithPng(figure, info, record.png, data.pngs[record.png], "llvmpipe", pixels, function () {
        return exactRecord(state) === record;
      });
    }

    // Greys out every axis value whose combination with the other current values the catalogue lacks.
    function markMissing() {
      program.axes.forEach(function (axis) {
        var input = axisInputs[axis.name];
        axis.values.forEach(function (value, i) {
          var wanted = Object.assign({}, state.defines);
          wanted[axis.name] = value;
          var exists = PrismWeb.findVariant(program, wanted) !== null;
          if (input.type === "checkbox") {
            if (value !== state.defines[axis.name]) input.disabled = !exists;
          } else input.options[i].disabled = !exists;
        });
        input.parentNode.classList.toggle("missing", input.disabled === true);
      });
    }

    function update(remeasure, quick) {
      if (!data.loaded[state.mesh]) return withMesh(state.mesh, function () { update(true); });
      try {
        drawInteractive(quick);
        if (remeasure) measure();
        markMissing();
        figure.removeAttribute("data-live-error");
      } catch (e) {
        figure.setAttribute("data-live-error", e.message);
        info.textContent = "error: " + e.message;
      }
    }

    this.buildControls = function (box) {
      program.axes.forEach(function (axis) {
        var boolean = axis.values.length === 2 && axis.values[0] === "0" && axis.values[1] === "1";
        var input = boolean ? control(box, axis.name, {type: "checkbox", "data-axis": axis.name}, function () {
          state.defines[axis.name] = input.checked ? "1" : "0"; update(true);
        }) : control(box, axis.name, {tag: "select"}, function () {
          state.defines[axis.name] = input.value; update(true);
        });
        if (boolean) input.checked = state.defines[axis.name] === "1";
        else axis.values.forEach(function (v) { element("option", {value: v}, input).textContent = v; });
        input.setAttribute("data-axis", axis.name);
        if (!boolean) input.value = state.defines[axis.name];
        axisInputs[axis.name] = input;
      });
      var meshSelect = control(box, "mesh", {tag: "select"}, function () { state.mesh = meshSelect.value; update(true); });
      data.meshNames.forEach(function (m) { element("option", {value: m}, meshSelect).textContent = m; });
      meshSelect.value = state.mesh;
      var u = first.uniforms, dir = u["u_lightDirection[0]"] || u.u_lightDirection || [-0.5, -0.6, -0.65];
      var azimuth = Math.atan2(-dir[0], -dir[2]), elevation = Math.asin(-dir[1] / Math.hypot(dir[0], dir[1], dir[2]));
      function setLight() {
        var az = +azInput.value * Math.PI / 180, el = +elInput.value * Math.PI / 180;
        state.overrides["u_lightDirection[0]"] = [-Math.cos(el) * Math.sin(az), -Math.sin(el), -Math.cos(el) * Math.cos(az)];
        update(false);
      }
      var azInput = control(box, "light azimuth", {type: "range", min: -180, max: 180, value: Math.round(azimuth * 180 / Math.PI)}, setLight);
      var elInput = control(box, "elevation", {type: "range", min: -89, max: 89, value: Math.round(elevation * 180 / Math.PI)}, setLight);
      var shininess = control(box, "shininess", {type: "range", min: 1, max: 256, value: (u.u_shininess || [48])[0]}, function () {
        state.overrides.u_shininess = [+shininess.value]; update(false);
      });
      var specular = control(box, "specular", {type: "range", min: 0, max: 1, step: 0.01, value: (u.u_specular || [0.6])[0]}, function () {
        state.overrides.u_specular = [+specular.value]; update(false);
      });
      var colour = control(box, "colour", {type: "color", value: hexColour(u.u_color || [0.85, 0.42, 0.25, 1])}, function () {
        var hex = colour.value, alpha = (u.u_color || [0, 0, 0, 1])[3];
        state.overrides.u_color = [1, 3, 5].map(function (i) { return parseInt(hex.substr(i, 2), 16) / 255; }).concat([alpha]);
        update(false);
      });
    };

    this.enableRotation = function () {
      var last = null;
      canvas.addEventListener("pointerdown", function (e) { last = [e.clientX, e.clientY]; canvas.setPointerCapture(e.pointerId); });
      canvas.addEventListener("pointerup", function () { last = null; update(false); });
      canvas.addEventListener("pointermove", function (e) {
        if (!last) return;
        state.angleY += (e.clientX - last[0]) * 0.01;
        state.angleX += (e.clientY - last[1]) * 0.01;
        last = [e.clientX, e.clientY];
        update(false, true);
      });
    };
    this.start = function () { update(true); };
  }

  function addView(shader) {
    var figure = element("figure", {"class": "live-view", id: "live-" + shader, "data-shader": shader}, section);
    var record = viewsOf(shader)[0];
    var canvas = element("canvas", {width: record.width, height: record.height, "class": "live-canvas"}, figure);
    var caption = element("figcaption", {}, figure);
    caption.textContent = shader + " (WebGL2, drag to rotate)";
    var view = new LiveView(shader, canvas, figure);
    view.buildControls(element("div", {"class": "live-controls"}, figure));
    view.enableRotation();
    view.start();
  }

  if (!gl) {
    status.textContent = "This browser has no WebGL2, so the live views are off; every PNG below still shows.";
    return;
  }
  var debug = gl.getExtension("WEBGL_debug_renderer_info");
  status.textContent = "Renderer: " + gl.getParameter(debug ? debug.UNMASKED_RENDERER_WEBGL : gl.RENDERER) +
                       ". Drawn live from the web catalogue " + data.catalogue +
                       "; beside each view, its agreement with prism-gallery's llvmpipe PNG.";
  data.shaders.filter(function (s) { return catalogue.programs[s]; }).forEach(addView);  // those with es300 texts
})();
