// pdesculpt gallery viewer: a binary glTF 2.0 (GLB) parser and a WebGL
// orbit view with per-part visibility toggles. No dependencies, no network:
// each model arrives as base64 through a classic script
// (`pdesculptGallery.register(name, b64)`), since a file:// page may not
// fetch files. Every `.viewer[data-model]` element gets a canvas; when its
// model is drawn, the element's data-status becomes "loaded" and
// data-meshes, data-triangles and data-height (metres, the y extent) are
// set for the browser test (verify/gallery/test.mjs); on failure
// data-status is "error" and the reason is logged with console.error.
(function () {
  'use strict';
  var models = {};

  function decode(b64) {
    var s = atob(b64);
    var u = new Uint8Array(s.length);
    for (var i = 0; i < s.length; i++) u[i] = s.charCodeAt(i);
    return u.buffer;
  }

  // Parts (one per primitive, as three.js makes one Mesh per primitive).
  function parseGlb(buf) {
    var dv = new DataView(buf);
    if (buf.byteLength < 20 || dv.getUint32(0, true) !== 0x46546c67) throw new Error('not a GLB file');
    if (dv.getUint32(4, true) !== 2) throw new Error('GLB version is not 2');
    var jsonLen = dv.getUint32(12, true);
    var json = JSON.parse(new TextDecoder().decode(new Uint8Array(buf, 20, jsonLen)));
    var binAt = 20 + jsonLen;
    var bin = buf.slice(binAt + 8, binAt + 8 + dv.getUint32(binAt, true));
    var cache = {};
    function accessor(i) {
      if (cache[i]) return cache[i];
      var a = json.accessors[i];
      var v = json.bufferViews[a.bufferView];
      var off = (v.byteOffset || 0) + (a.byteOffset || 0);
      var n = a.count * ({ SCALAR: 1, VEC2: 2, VEC3: 3, VEC4: 4 })[a.type];
      var T = ({ 5126: Float32Array, 5125: Uint32Array, 5123: Uint16Array, 5121: Uint8Array })[a.componentType];
      if (!T) throw new Error('unsupported accessor component type ' + a.componentType);
      cache[i] = { index: i, data: new T(bin, off, n) };
      return cache[i];
    }
    var parts = [];
    (json.meshes || []).forEach(function (m) {
      m.primitives.forEach(function (p, k) {
        if ((p.mode === undefined ? 4 : p.mode) !== 4) throw new Error('only triangle primitives are supported');
        var mat = (json.materials || [])[p.material] || {};
        var pbr = mat.pbrMetallicRoughness || {};
        parts.push({
          name: mat.name || (m.name || 'mesh') + ' ' + k,
          color: pbr.baseColorFactor || [0.8, 0.8, 0.8, 1],
          position: accessor(p.attributes.POSITION),
          normal: p.attributes.NORMAL === undefined ? null : accessor(p.attributes.NORMAL),
          indices: accessor(p.indices)
        });
      });
    });
    if (!parts.length) throw new Error('the GLB has no mesh primitives');
    return parts;
  }

  // Column-major 4x4 matrices.
  function perspective(fovy, aspect, near, far) {
    var f = 1 / Math.tan(fovy / 2), nf = 1 / (near - far);
    return [f / aspect, 0, 0, 0, 0, f, 0, 0, 0, 0, (far + near) * nf, -1, 0, 0, 2 * far * near * nf, 0];
  }
  function lookAt(e, t, up) {
    var z = norm([e[0] - t[0], e[1] - t[1], e[2] - t[2]]);
    var x = norm(cross(up, z)), y = cross(z, x);
    return [x[0], y[0], z[0], 0, x[1], y[1], z[1], 0, x[2], y[2], z[2], 0,
      -dot(x, e), -dot(y, e), -dot(z, e), 1];
  }
  function mul(a, b) {
    var o = new Array(16);
    for (var c = 0; c < 4; c++) for (var r = 0; r < 4; r++) {
      var s = 0;
      for (var k = 0; k < 4; k++) s += a[k * 4 + r] * b[c * 4 + k];
      o[c * 4 + r] = s;
    }
    return o;
  }
  function cross(a, b) { return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]; }
  function dot(a, b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
  function norm(a) { var l = Math.sqrt(dot(a, a)) || 1; return [a[0] / l, a[1] / l, a[2] / l]; }

  var VS = 'attribute vec3 p; attribute vec3 n; uniform mat4 mvp; varying vec3 vn; varying vec3 vp;' +
    'void main(){ vn = n; vp = p; gl_Position = mvp * vec4(p, 1.0); }';
  var FS = 'precision mediump float; uniform vec3 color; uniform vec3 eye; varying vec3 vn; varying vec3 vp;' +
    'void main(){ float l = abs(dot(normalize(vn), normalize(eye - vp)));' +
    ' gl_FragColor = vec4(color * (0.3 + 0.7 * l), 1.0); }';

  function shader(gl, type, src) {
    var s = gl.createShader(type);
    gl.shaderSource(s, src);
    gl.compileShader(s);
    if (!gl.getShaderParameter(s, gl.COMPILE_STATUS)) throw new Error('shader: ' + gl.getShaderInfoLog(s));
    return s;
  }

  function mount(el, parts) {
    var canvas = document.createElement('canvas');
    el.appendChild(canvas);
    var gl = canvas.getContext('webgl2') || canvas.getContext('webgl');
    if (!gl) throw new Error('WebGL is not available');
    var u32 = (typeof WebGL2RenderingContext !== 'undefined' && gl instanceof WebGL2RenderingContext) ||
      gl.getExtension('OES_element_index_uint');
    var prog = gl.createProgram();
    gl.attachShader(prog, shader(gl, gl.VERTEX_SHADER, VS));
    gl.attachShader(prog, shader(gl, gl.FRAGMENT_SHADER, FS));
    gl.linkProgram(prog);
    if (!gl.getProgramParameter(prog, gl.LINK_STATUS)) throw new Error('link: ' + gl.getProgramInfoLog(prog));
    var loc = { p: gl.getAttribLocation(prog, 'p'), n: gl.getAttribLocation(prog, 'n'),
      mvp: gl.getUniformLocation(prog, 'mvp'), color: gl.getUniformLocation(prog, 'color'),
      eye: gl.getUniformLocation(prog, 'eye') };
    var buffers = {};
    function vbo(acc) {
      if (!buffers[acc.index]) {
        buffers[acc.index] = gl.createBuffer();
        gl.bindBuffer(gl.ARRAY_BUFFER, buffers[acc.index]);
        gl.bufferData(gl.ARRAY_BUFFER, acc.data, gl.STATIC_DRAW);
      }
      return buffers[acc.index];
    }
    var lo = [Infinity, Infinity, Infinity], hi = [-Infinity, -Infinity, -Infinity], triangles = 0;
    parts.forEach(function (part) {
      var pos = part.position.data, idx = part.indices.data;
      for (var i = 0; i < idx.length; i++) {
        for (var k = 0; k < 3; k++) {
          var x = pos[3 * idx[i] + k];
          if (x < lo[k]) lo[k] = x;
          if (x > hi[k]) hi[k] = x;
        }
      }
      triangles += idx.length / 3;
      part.vbo = vbo(part.position);
      part.nbo = part.normal ? vbo(part.normal) : null;
      var data = idx;
      if (idx instanceof Uint32Array && !u32) throw new Error('32-bit indices need OES_element_index_uint');
      part.type = idx instanceof Uint32Array ? gl.UNSIGNED_INT : idx instanceof Uint16Array ? gl.UNSIGNED_SHORT : gl.UNSIGNED_BYTE;
      part.ibo = gl.createBuffer();
      gl.bindBuffer(gl.ELEMENT_ARRAY_BUFFER, part.ibo);
      gl.bufferData(gl.ELEMENT_ARRAY_BUFFER, data, gl.STATIC_DRAW);
      part.count = idx.length;
      part.visible = true;
    });
    var centre = [0, 1, 2].map(function (k) { return 0.5 * (lo[k] + hi[k]); });
    var radius = 0.5 * Math.sqrt(dot([hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]], [hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]])) || 1;
    var view = { yaw: 0.5, pitch: 0.15, dist: 2.6 * radius };
    var queued = false;
    function draw() {
      queued = false;
      var w = canvas.clientWidth, h = canvas.clientHeight, dpr = window.devicePixelRatio || 1;
      if (canvas.width !== Math.round(w * dpr) || canvas.height !== Math.round(h * dpr)) {
        canvas.width = Math.round(w * dpr);
        canvas.height = Math.round(h * dpr);
      }
      gl.viewport(0, 0, canvas.width, canvas.height);
      gl.clearColor(0.96, 0.96, 0.97, 1);
      gl.clear(gl.COLOR_BUFFER_BIT | gl.DEPTH_BUFFER_BIT);
      gl.enable(gl.DEPTH_TEST);
      gl.useProgram(prog);
      var cp = Math.cos(view.pitch);
      var eye = [centre[0] + view.dist * cp * Math.sin(view.yaw), centre[1] + view.dist * Math.sin(view.pitch),
        centre[2] + view.dist * cp * Math.cos(view.yaw)];
      var mvp = mul(perspective(0.7, canvas.width / Math.max(1, canvas.height), view.dist / 100, view.dist * 10),
        lookAt(eye, centre, [0, 1, 0]));
      gl.uniformMatrix4fv(loc.mvp, false, new Float32Array(mvp));
      gl.uniform3fv(loc.eye, new Float32Array(eye));
      parts.forEach(function (part) {
        if (!part.visible) return;
        gl.bindBuffer(gl.ARRAY_BUFFER, part.vbo);
        gl.enableVertexAttribArray(loc.p);
        gl.vertexAttribPointer(loc.p, 3, gl.FLOAT, false, 0, 0);
        if (part.nbo && loc.n >= 0) {
          gl.bindBuffer(gl.ARRAY_BUFFER, part.nbo);
          gl.enableVertexAttribArray(loc.n);
          gl.vertexAttribPointer(loc.n, 3, gl.FLOAT, false, 0, 0);
        } else if (loc.n >= 0) {
          gl.disableVertexAttribArray(loc.n);
          gl.vertexAttrib3f(loc.n, 0, 0, 1);
        }
        gl.uniform3f(loc.color, part.color[0], part.color[1], part.color[2]);
        gl.bindBuffer(gl.ELEMENT_ARRAY_BUFFER, part.ibo);
        gl.drawElements(gl.TRIANGLES, part.count, part.type, 0);
      });
      var err = gl.getError();
      if (err !== gl.NO_ERROR) console.error('viewer ' + el.dataset.model + ': WebGL error ' + err);
    }
    function redraw() { if (!queued) { queued = true; requestAnimationFrame(draw); } }
    var drag = null;
    canvas.addEventListener('pointerdown', function (e) { drag = [e.clientX, e.clientY]; canvas.setPointerCapture(e.pointerId); });
    canvas.addEventListener('pointerup', function () { drag = null; });
    canvas.addEventListener('pointermove', function (e) {
      if (!drag) return;
      view.yaw -= 0.01 * (e.clientX - drag[0]);
      view.pitch = Math.max(-1.5, Math.min(1.5, view.pitch + 0.01 * (e.clientY - drag[1])));
      drag = [e.clientX, e.clientY];
      redraw();
    });
    canvas.addEventListener('wheel', function (e) {
      e.preventDefault();
      view.dist = Math.max(0.2 * radius, Math.min(20 * radius, view.dist * Math.exp(0.001 * e.deltaY)));
      redraw();
    }, { passive: false });
    canvas.addEventListener('dblclick', function () { view.yaw = 0.5; view.pitch = 0.15; view.dist = 2.6 * radius; redraw(); });
    window.addEventListener('resize', redraw);
    var toggles = document.createElement('div');
    toggles.className = 'toggles';
    parts.forEach(function (part) {
      var label = document.createElement('label');
      var box = document.createElement('input');
      box.type = 'checkbox';
      box.checked = true;
      box.dataset.part = part.name;
      box.addEventListener('change', function () { part.visible = box.checked; redraw(); });
      var sw = document.createElement('span');
      sw.className = 'swatch';
      sw.style.background = 'rgb(' + part.color.slice(0, 3).map(function (c) { return Math.round(255 * c); }).join(',') + ')';
      label.appendChild(box);
      label.appendChild(sw);
      label.appendChild(document.createTextNode(part.name));
      toggles.appendChild(label);
    });
    el.appendChild(toggles);
    draw();
    el.dataset.meshes = String(parts.length);
    el.dataset.triangles = String(triangles);
    el.dataset.height = String(hi[1] - lo[1]);
    el.dataset.status = 'loaded';
    window.pdesculptGallery.viewers[el.dataset.model] = { parts: parts, view: view, redraw: redraw };
  }

  function fail(el, e) {
    el.dataset.status = 'error';
    el.textContent = 'could not show ' + el.dataset.model + ': ' + e.message;
    console.error('viewer ' + el.dataset.model + ': ' + e.message);
  }

  function mountAll(final) {
    var els = document.querySelectorAll('.viewer[data-status="loading"]');
    for (var i = 0; i < els.length; i++) {
      var el = els[i], name = el.dataset.model;
      if (models[name] !== undefined) {
        try { mount(el, parseGlb(decode(models[name]))); } catch (e) { fail(el, e); }
      } else if (final) {
        fail(el, new Error('its model script gallery/' + name + '.js did not load'));
      }
    }
  }

  window.pdesculptGallery = {
    viewers: {},
    register: function (name, b64) {
      models[name] = b64;
      if (document.readyState !== 'loading') mountAll(false);
    }
  };
  document.addEventListener('DOMContentLoaded', function () { mountAll(false); });
  window.addEventListener('load', function () { mountAll(true); });
})();
