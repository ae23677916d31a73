// The script of the `massprops view` page (after three.js r111 and its OrbitControls in the same
// script element). It reads the JSON block #massprops-data (written by src/tool/view_command.cc; schema in
// docs/view.md) and draws, in the model frame (the root link's frame, z up): each link's collision
// geometry, its equivalent uniform box or ellipsoid at its center of mass along its principal
// axes, COM markers, and on demand the welded groups' composite boxes. The link list, the details
// of the selected link and the summary are plain DOM. State for tests: window.massprops.
(function () {
  'use strict';

  var timing = { script: performance.now() };
  var data = JSON.parse(document.getElementById('massprops-data').textContent);
  timing.data = performance.now();
  var SEVERITY_RANK = { note: 0, warning: 1, error: 2 };

  // ------------------------------------------------------------------ helpers
  function fmt(x) {
    if (x === null || x === undefined || typeof x !== 'number' || !isFinite(x)) return '—';
    if (x === 0) return '0';
    var a = Math.abs(x);
    if (a >= 1e-3 && a < 1e5) return String(Number(x.toPrecision(5)));
    return x.toExponential(3);
  }
  function fmtVec(v) {
    return v ? v.map(fmt).join('  ') : '—';
  }
  function fmtShort(x) {
    if (typeof x !== 'number' || !isFinite(x)) return '—';
    return x === 0 ? '0' : Number(x.toPrecision(3)).toExponential().replace(/\.?0*e/, 'e').replace('e+0', '').replace(/e\+?/, 'e');
  }
  function el(tag, attrs, children) {
    var node = document.createElement(tag);
    if (attrs) {
      Object.keys(attrs).forEach(function (k) {
        if (k === 'text') node.textContent = attrs[k];
        else if (k === 'class') node.className = attrs[k];
        else node.setAttribute(k, attrs[k]);
      });
    }
    (children || []).forEach(function (c) {
      node.appendChild(typeof c === 'string' ? document.createTextNode(c) : c);
    });
    return node;
  }
  function where(file, line) {
    return (file || '') + (line > 0 ? ':' + line : '');
  }
  function cssColor(name) {
    return getComputedStyle(document.documentElement).getPropertyValue(name).trim() || '#888888';
  }
  function worstSeverity(findings) {
    var worst = null;
    findings.forEach(function (f) {
      if (worst === null || SEVERITY_RANK[f.severity] > SEVERITY_RANK[worst]) worst = f.severity;
    });
    return worst;
  }
  function countBySeverity(findings) {
    var counts = { error: 0, warning: 0, note: 0 };
    findings.forEach(function (f) { counts[f.severity] = (counts[f.severity] || 0) + 1; });
    return counts;
  }
  function badges(findings) {
    var counts = countBySeverity(findings);
    var out = [];
    ['error', 'warning', 'note'].forEach(function (s) {
      if (counts[s] > 0) out.push(el('span', { class: 'badge ' + s, text: String(counts[s]), title: counts[s] + ' ' + s + (counts[s] > 1 ? 's' : '') }));
    });
    return out;
  }

  // ------------------------------------------------------------------ the links
  // One record per link of every model: its data, its key, its severity and its 3D objects.
  var records = [];
  var recordByKey = {};
  data.models.forEach(function (model, mi) {
    model.links.forEach(function (link) {
      var rec = {
        key: mi + ':' + link.name, model: model, modelIndex: mi, link: link,
        severity: worstSeverity(link.findings), drawn: link.box !== null,
        box: null, ellipsoid: null, com: null, geometry: [], row: null
      };
      records.push(rec);
      recordByKey[rec.key] = rec;
    });
  });

  var state = {
    links: records.filter(function (r) { return r.drawn; }).map(function (r) {
      return {
        name: r.link.name, model: r.model.name, mass: r.link.mass, box: r.link.box.slice(),
        ellipsoid: r.link.ellipsoid.slice(), box_exists: r.link.box_exists,
        principal_moments: r.link.principal_moments.slice(), severity: r.severity,
        findings: r.link.findings.length
      };
    }),
    selected: null,
    selectedModel: null,
    shape: 'box',
    webgl: false,
    ready: false,
    scene: { boxes: 0, ellipsoids: 0, geometries: 0, meshes: 0, geometry_errors: 0 },
    // Where a link's center of mass is drawn, in CSS pixels from the view's top-left corner
    // (null without WebGL or for a link not drawn): for tests that click in the view.
    screenPosition: function (name) {
      var rec = records.filter(function (r) { return r.link.name === name && r.drawn; })[0];
      if (!rec || !renderer) return null;
      var v = new THREE.Vector3().fromArray(rec.link.com).project(camera);
      var r = renderer.domElement.getBoundingClientRect();
      return [(v.x + 1) / 2 * r.width, (1 - v.y) / 2 * r.height];
    },
    select: function (name, model) {
      var rec = records.filter(function (r) {
        return r.link.name === name && (model === undefined || r.model.name === model);
      })[0];
      select(rec || null);
      return !!rec;
    }
  };
  window.massprops = state;

  // ------------------------------------------------------------------ summary and list
  var allFindings = [];
  data.models.forEach(function (m) {
    allFindings = allFindings.concat(m.findings);
    m.links.forEach(function (l) { allFindings = allFindings.concat(l.findings); });
  });
  (function summary() {
    var node = document.getElementById('summary');
    var parts = [];
    data.models.forEach(function (m) {
      parts.push(el('b', { text: m.name || '(unnamed)' }));
      parts.push(' · ' + m.links.length + ' links · ' + fmt(m.total.mass) + ' kg · ');
    });
    var counts = countBySeverity(allFindings);
    parts.push(counts.error + ' errors, ' + counts.warning + ' warnings');
    if (data.errors.length) parts.push(el('span', { class: 'error-text', text: ', ' + data.errors.length + ' read errors' }));
    parts.forEach(function (p) { node.appendChild(typeof p === 'string' ? document.createTextNode(p) : p); });
  })();

  var tbody = document.querySelector('#links tbody');
  records.forEach(function (rec) {
    var l = rec.link;
    var name = data.models.length > 1 ? rec.model.name + ' / ' + l.name : l.name;
    var row = el('tr', { 'data-link': l.name, 'data-model': rec.model.name, class: rec.drawn ? '' : 'massless' }, [
      el('td', { text: name }),
      el('td', { class: 'num', text: fmt(l.mass) }),
      el('td', { class: 'num', text: rec.drawn ? l.principal_moments.map(fmtShort).join(' ') : '' }),
      el('td', {}, badges(l.findings))
    ]);
    row.addEventListener('click', function () { select(rec); });
    rec.row = row;
    tbody.appendChild(row);
  });
  document.getElementById('only-findings').addEventListener('change', function (e) {
    records.forEach(function (rec) {
      rec.row.hidden = e.target.checked && rec.link.findings.length === 0;
    });
  });

  // A finding as `massprops check` words it: "severity: HEADLINE [rule]", then its evidence and
  // help; the full reasoning (check --explain's "why") in the headline's tooltip.
  function findingNode(f) {
    var parts = [
      el('div', { title: f.message }, [el('b', { text: f.severity + ': ' }), f.headline + ' ',
                                       el('code', { text: '[' + f.rule + ']' }),
                                       f.fixed_by_repair ? ' (fix repairs this)' : ''])];
    if (f.evidence) parts.push(el('div', { class: 'where', text: 'evidence: ' + f.evidence }));
    if (f.help) parts.push(el('div', { class: 'where', text: 'help: ' + f.help }));
    parts.push(el('div', { class: 'where', text: where(f.file, f.line) }));
    return el('div', { class: 'finding ' + f.severity }, parts);
  }

  function showOverview() {
    var node = document.getElementById('details');
    node.textContent = '';
    data.errors.forEach(function (e) {
      node.appendChild(el('div', { class: 'finding error' }, [
        el('div', { title: e.message }, [el('b', { text: 'error: ' }), e.headline + ' ',
                                         el('code', { text: '[read-error]' })]),
        e.headline === e.message ? '' : el('div', { class: 'where', text: 'why: ' + e.message }),
        el('div', { class: 'where', text: where(e.file, e.line) })]));
    });
    data.models.forEach(function (m) {
      node.appendChild(el('h2', { text: (m.name || '(unnamed)') + ' (' + m.format + ')' }));
      node.appendChild(el('table', {}, [
        el('tr', {}, [el('td', { text: 'file' }), el('td', { text: m.file })]),
        el('tr', {}, [el('td', { text: 'total mass' }), el('td', { text: fmt(m.total.mass) + ' kg' })]),
        el('tr', {}, [el('td', { text: 'center of mass' }), el('td', { text: fmtVec(m.total.com) + ' m in ' + m.root_link })]),
        el('tr', {}, [el('td', { text: 'principal moments' }), el('td', { text: fmtVec(m.total.principal_moments) + ' kg·m²' })]),
        el('tr', {}, [el('td', { text: 'welded groups' }), el('td', { text: m.groups.length + ' of two links or more' })])
      ]));
      if (m.unreachable_links.length) {
        node.appendChild(el('div', { text: 'Not in the total (not reachable from ' + m.root_link + '): ' + m.unreachable_links.join(', ') }));
      }
      m.findings.forEach(function (f) { node.appendChild(findingNode(f)); });
    });
    node.appendChild(el('p', { class: 'where', text: 'Click a link here or in the view. Drag: orbit; wheel: zoom; right drag: pan.' }));
  }

  function showLink(rec) {
    var l = rec.link;
    var node = document.getElementById('details');
    node.textContent = '';
    node.appendChild(el('h2', { text: l.name }));
    var rows = [
      ['mass', fmt(l.mass) + ' kg' + (l.has_inertial ? '' : ' (no <inertial>)')],
      ['COM in link frame', fmtVec(l.com_link) + ' m'],
      ['COM in model frame', fmtVec(l.com) + ' m'],
      ['principal moments', fmtVec(l.principal_moments) + ' kg·m²'],
      ['equivalent box', l.box ? fmtVec(l.box) + ' m' + (l.box_exists ? '' : ' (no such box: the moments break the triangle inequality; sides clamped at 0)') : 'none (no positive mass)'],
      ['equivalent ellipsoid', l.ellipsoid ? fmtVec(l.ellipsoid) + ' m (semi-axes)' : '—'],
      ['inertia about COM', fmtVec(l.inertia_about_com.slice(0, 3)) + ' / ' + fmtVec(l.inertia_about_com.slice(3, 6)) + ' / ' + fmtVec(l.inertia_about_com.slice(6, 9))],
      ['defined at', where(l.file, l.line)]
    ];
    if (!l.reachable) rows.push(['pose', 'not reachable from the root link: drawn at the model origin']);
    node.appendChild(el('table', {}, rows.map(function (r) {
      return el('tr', {}, [el('td', { text: r[0] }), el('td', { text: r[1] })]);
    })));
    l.geometry.forEach(function (g) {
      if (g.error) node.appendChild(el('div', { class: 'where', text: 'mesh ' + g.uri + ' not drawn: ' + g.error }));
    });
    if (l.findings.length === 0) node.appendChild(el('p', { text: 'No findings.' }));
    l.findings.forEach(function (f) { node.appendChild(findingNode(f)); });
    node.appendChild(el('div', { class: 'repair' }, [
      el('b', { text: 'massprops fix: ' }),
      l.repair ? l.repair : 'no repair for this link'
    ]));
  }

  // ------------------------------------------------------------------ 3D
  var view = document.getElementById('view');
  var renderer = null, scene, camera, controls, home = null;
  var groupsLayer, boxesLayer, ellipsoidsLayer, geometryLayer, comLayer;
  var pickables = [];
  var renderPending = false;

  function webglAvailable() {
    try {
      var canvas = document.createElement('canvas');
      return !!(window.WebGLRenderingContext && (canvas.getContext('webgl') || canvas.getContext('experimental-webgl')));
    } catch (e) {
      return false;
    }
  }

  function render() {
    if (renderer) renderer.render(scene, camera);
  }
  function requestRender() {
    if (renderPending || !renderer) return;
    renderPending = true;
    requestAnimationFrame(function () { renderPending = false; render(); });
  }

  function matrixFromPose(pose) {
    var R = pose.R, p = pose.p;
    return new THREE.Matrix4().set(R[0], R[1], R[2], p[0], R[3], R[4], R[5], p[1],
                                   R[6], R[7], R[8], p[2], 0, 0, 0, 1);
  }
  // The matrix taking the unit body to the body: columns = principal axes × sizes, at the COM.
  function matrixFromBody(axes, sizes, com) {
    var s = sizes.slice();
    var largest = Math.max(s[0], s[1], s[2]);
    for (var k = 0; k < 3; ++k) if (!(s[k] > 0)) s[k] = Math.max(largest * 0.01, 1e-6);
    var A = axes;
    return new THREE.Matrix4().set(A[0] * s[0], A[1] * s[1], A[2] * s[2], com[0],
                                   A[3] * s[0], A[4] * s[1], A[5] * s[2], com[1],
                                   A[6] * s[0], A[7] * s[1], A[8] * s[2], com[2], 0, 0, 0, 1);
  }
  function place(object, matrix) {
    object.matrixAutoUpdate = false;
    object.matrix.copy(matrix);
    object.updateMatrixWorld(true);
    return object;
  }

  var unitBox, unitBoxEdges, unitSphere, unitSphereLowRes;
  var colors = {};
  var geometryMaterials = {};
  var meshGeometries = [];

  function severityColor(sev) {
    return sev === 'error' ? colors.error : sev === 'warning' ? colors.warning : colors.ok;
  }

  function readColors() {
    colors.ok = new THREE.Color(cssColor('--ok'));
    colors.warning = new THREE.Color(cssColor('--warning'));
    colors.error = new THREE.Color(cssColor('--error'));
    colors.select = new THREE.Color(cssColor('--select'));
    colors.background = new THREE.Color(cssColor('--view-bg'));
    colors.fg = new THREE.Color(cssColor('--fg'));
    colors.geometry = new THREE.Color(cssColor('--muted'));
  }

  function buildMeshGeometry(mesh) {
    var n = mesh.q.length;
    var positions = new Float32Array(n);
    for (var i = 0; i < n; i += 3) {
      positions[i] = mesh.min[0] + mesh.q[i] * mesh.step[0];
      positions[i + 1] = mesh.min[1] + mesh.q[i + 1] * mesh.step[1];
      positions[i + 2] = mesh.min[2] + mesh.q[i + 2] * mesh.step[2];
    }
    var g = new THREE.BufferGeometry();
    g.setAttribute('position', new THREE.BufferAttribute(positions, 3));
    var index = (n / 3 > 65535) ? new Uint32Array(mesh.t) : new Uint16Array(mesh.t);
    g.setIndex(new THREE.BufferAttribute(index, 1));
    g.computeVertexNormals();
    return g;
  }

  function geometryObject(g, material) {
    var object = null;
    if (g.type === 'box') {
      object = new THREE.Mesh(unitBox, material);
      object.matrix.makeScale(g.size[0], g.size[1], g.size[2]);
    } else if (g.type === 'sphere') {
      object = new THREE.Mesh(unitSphere, material);
      object.matrix.makeScale(g.radius, g.radius, g.radius);
    } else if (g.type === 'ellipsoid') {
      object = new THREE.Mesh(unitSphere, material);
      object.matrix.makeScale(g.radii[0], g.radii[1], g.radii[2]);
    } else if (g.type === 'cylinder' || g.type === 'capsule') {
      // three's cylinder runs along y; URDF and SDF cylinders along z.
      object = new THREE.Group();
      var body = new THREE.Mesh(new THREE.CylinderBufferGeometry(g.radius, g.radius, g.length, 24), material);
      body.rotation.x = Math.PI / 2;
      object.add(body);
      if (g.type === 'capsule') {
        [-1, 1].forEach(function (side) {
          var cap = new THREE.Mesh(unitSphereLowRes, material);
          cap.scale.set(g.radius, g.radius, g.radius);
          cap.position.z = side * g.length / 2;
          object.add(cap);
        });
      }
    } else if (g.type === 'mesh' && g.mesh !== undefined) {
      object = new THREE.Mesh(meshGeometries[g.mesh], material);
      state.scene.meshes += 1;
    }
    if (!object) return null;
    var local = object.matrix.clone();
    if (object.type === 'Group') local.identity();
    object.matrixAutoUpdate = false;
    object.matrix.multiplyMatrices(matrixFromPose(g.pose), local);
    object.updateMatrixWorld(true);
    return object;
  }

  // Every surface is drawn with one kind of material (Lambert, one side), so that the page
  // compiles one surface shader program (slow in a software WebGL) besides the lines' one.
  // COM markers: unlit, by emission only.
  function flatMaterial(color) {
    return new THREE.MeshLambertMaterial({ color: 0x000000, emissive: color });
  }

  // The box of a drawn object: from its geometry's box (8 corners) for a mesh, rather than
  // three's expandByObject, which visits every vertex.
  function expandBounds(bounds, object) {
    if (object.isMesh) {
      if (!object.geometry.boundingBox) object.geometry.computeBoundingBox();
      bounds.union(object.geometry.boundingBox.clone().applyMatrix4(object.matrixWorld));
    } else {
      bounds.expandByObject(object);
    }
  }

  function boxMaterial(rec) {
    return new THREE.MeshLambertMaterial({
      color: severityColor(rec.severity), transparent: true, opacity: 0.45, depthWrite: false
    });
  }

  function initScene() {
    readColors();
    renderer = new THREE.WebGLRenderer({ antialias: true });
    renderer.setPixelRatio(window.devicePixelRatio || 1);
    renderer.setClearColor(colors.background, 1);
    view.appendChild(renderer.domElement);
    scene = new THREE.Scene();
    camera = new THREE.PerspectiveCamera(40, 1, 0.001, 1000);
    camera.up.set(0, 0, 1);
    scene.add(new THREE.HemisphereLight(0xffffff, 0x606060, 0.85));
    var sun = new THREE.DirectionalLight(0xffffff, 0.55);
    sun.position.set(1, 0.6, 2);
    scene.add(sun);

    unitBox = new THREE.BoxBufferGeometry(1, 1, 1);
    unitBoxEdges = new THREE.EdgesGeometry(unitBox);
    unitSphere = new THREE.SphereBufferGeometry(1, 24, 16);
    unitSphereLowRes = new THREE.SphereBufferGeometry(1, 12, 8);
    data.meshes.forEach(function (m) { meshGeometries.push(buildMeshGeometry(m)); });

    ['ok', 'warning', 'error'].forEach(function (sev) {
      var c = colors.geometry.clone().lerp(sev === 'ok' ? colors.geometry : severityColor(sev), 0.45);
      geometryMaterials[sev] = new THREE.MeshLambertMaterial({
        color: c, transparent: true, opacity: 0.35, depthWrite: false
      });
    });

    geometryLayer = new THREE.Group();
    boxesLayer = new THREE.Group();
    ellipsoidsLayer = new THREE.Group();
    comLayer = new THREE.Group();
    groupsLayer = new THREE.Group();
    ellipsoidsLayer.visible = false;
    groupsLayer.visible = false;
    [geometryLayer, boxesLayer, ellipsoidsLayer, comLayer, groupsLayer].forEach(function (g) { scene.add(g); });

    var bounds = new THREE.Box3();
    records.forEach(function (rec) {
      var l = rec.link;
      var gm = geometryMaterials[rec.severity === 'error' || rec.severity === 'warning' ? rec.severity : 'ok'];
      l.geometry.forEach(function (g) {
        if (g.error) { state.scene.geometry_errors += 1; return; }
        var object = geometryObject(g, gm);
        if (!object) return;
        object.userData.record = rec;
        geometryLayer.add(object);
        pickables.push(object);
        rec.geometry.push(object);
        state.scene.geometries += 1;
        expandBounds(bounds, object);
      });
      if (!rec.drawn) return;
      rec.material = boxMaterial(rec);
      rec.edgeMaterial = new THREE.LineBasicMaterial({ color: severityColor(rec.severity) });
      var boxMatrix = matrixFromBody(l.axes, l.box, l.com);
      rec.box = place(new THREE.Mesh(unitBox, rec.material), boxMatrix);
      rec.box.userData.record = rec;
      rec.box.userData.kind = 'inertia-box';
      rec.box.add(new THREE.LineSegments(unitBoxEdges, rec.edgeMaterial));
      boxesLayer.add(rec.box);
      state.scene.boxes += 1;
      var ellMatrix = matrixFromBody(l.axes, l.ellipsoid, l.com);
      rec.ellipsoid = place(new THREE.Mesh(unitSphere, rec.material), ellMatrix);
      rec.ellipsoid.userData.record = rec;
      rec.ellipsoid.userData.kind = 'inertia-ellipsoid';
      ellipsoidsLayer.add(rec.ellipsoid);
      state.scene.ellipsoids += 1;
      pickables.push(rec.box, rec.ellipsoid);
      expandBounds(bounds, rec.box);
    });
    if (bounds.isEmpty()) bounds.set(new THREE.Vector3(-0.5, -0.5, -0.5), new THREE.Vector3(0.5, 0.5, 0.5));
    var size = bounds.getSize(new THREE.Vector3()).length() || 1;
    var center = bounds.getCenter(new THREE.Vector3());

    // COM markers: one per drawn link, and the model's total (larger, in the text colour).
    var markerRadius = size * 0.008;
    records.forEach(function (rec) {
      if (!rec.drawn) return;
      rec.com = new THREE.Mesh(unitSphereLowRes, flatMaterial(severityColor(rec.severity)));
      rec.com.scale.setScalar(markerRadius);
      rec.com.position.fromArray(rec.link.com);
      rec.com.userData.record = rec;
      comLayer.add(rec.com);
    });
    data.models.forEach(function (m) {
      if (!(m.total.mass > 0)) return;
      var total = new THREE.Mesh(unitSphereLowRes, flatMaterial(colors.fg));
      total.scale.setScalar(markerRadius * 2.2);
      total.position.fromArray(m.total.com);
      comLayer.add(total);
    });
    // Welded groups of two links or more: their composite box, as edges.
    data.models.forEach(function (m) {
      m.groups.forEach(function (g) {
        if (!g.box) return;
        var lines = place(new THREE.LineSegments(unitBoxEdges, new THREE.LineBasicMaterial({ color: 0x8250df })),
                          matrixFromBody(g.axes, g.box, g.com));
        lines.userData.group = g.root;
        groupsLayer.add(lines);
      });
    });

    camera.near = size / 1000;
    camera.far = size * 100;
    var dir = new THREE.Vector3(1.0, -1.6, 0.9).normalize();
    home = { target: center.clone(), position: center.clone().addScaledVector(dir, size * 1.4) };
    controls = new THREE.OrbitControls(camera, renderer.domElement);
    controls.screenSpacePanning = true;
    controls.addEventListener('change', requestRender);
    resetView();
    resize();
  }

  function resetView() {
    if (!renderer) return;
    camera.position.copy(home.position);
    controls.target.copy(home.target);
    camera.updateProjectionMatrix();
    controls.update();
    requestRender();
  }

  function resize() {
    if (!renderer) return;
    var w = Math.max(1, view.clientWidth), h = Math.max(1, view.clientHeight);
    renderer.setSize(w, h, false);
    renderer.domElement.style.width = '100%';
    renderer.domElement.style.height = '100%';
    camera.aspect = w / h;
    camera.updateProjectionMatrix();
    render();
  }

  // Selection: the list row, the details, and the box drawn opaque with edges in the selection
  // colour (the others fade).
  var current = null;
  function styleRecord(rec, selected, anySelected) {
    if (!rec.material) return;
    rec.material.opacity = selected ? 0.75 : anySelected ? 0.2 : 0.45;
    rec.edgeMaterial.color.copy(selected ? colors.select : severityColor(rec.severity));
  }
  function select(rec) {
    if (current && current.row) current.row.classList.remove('selected');
    current = rec;
    state.selected = rec ? rec.link.name : null;
    state.selectedModel = rec ? rec.model.name : null;
    if (renderer) records.forEach(function (r) { styleRecord(r, r === rec, !!rec); });
    if (rec) {
      rec.row.classList.add('selected');
      if (rec.row.scrollIntoView && !rec.row.hidden) rec.row.scrollIntoView({ block: 'nearest' });
      showLink(rec);
    } else {
      showOverview();
    }
    requestRender();
  }

  // Click (not drag) in the view picks the nearest link under the pointer.
  function setupPicking() {
    var down = null;
    var raycaster = new THREE.Raycaster();
    renderer.domElement.addEventListener('pointerdown', function (e) { down = [e.clientX, e.clientY]; });
    renderer.domElement.addEventListener('pointerup', function (e) {
      if (!down || Math.abs(e.clientX - down[0]) + Math.abs(e.clientY - down[1]) > 4) return;
      var r = renderer.domElement.getBoundingClientRect();
      var ndc = new THREE.Vector2(((e.clientX - r.left) / r.width) * 2 - 1, -((e.clientY - r.top) / r.height) * 2 + 1);
      raycaster.setFromCamera(ndc, camera);
      var visible = pickables.filter(function (o) {
        for (var p = o; p; p = p.parent) if (!p.visible) return false;
        return true;
      });
      var hits = raycaster.intersectObjects(visible, true);
      for (var i = 0; i < hits.length; ++i) {
        for (var o = hits[i].object; o; o = o.parent) {
          if (o.userData.record) { select(o.userData.record); return; }
        }
      }
      select(null);
    });
  }

  function setupToolbar() {
    function toggle(id, apply) {
      var box = document.getElementById(id);
      box.addEventListener('change', function () { apply(box.checked); requestRender(); });
    }
    toggle('show-geometry', function (on) { if (geometryLayer) geometryLayer.visible = on; });
    toggle('show-com', function (on) { if (comLayer) comLayer.visible = on; });
    toggle('show-groups', function (on) { if (groupsLayer) groupsLayer.visible = on; });
    function showShape() {
      var on = document.getElementById('show-boxes').checked;
      state.shape = document.getElementById('shape').value;
      if (boxesLayer) {
        boxesLayer.visible = on && state.shape === 'box';
        ellipsoidsLayer.visible = on && state.shape === 'ellipsoid';
      }
      requestRender();
    }
    document.getElementById('show-boxes').addEventListener('change', showShape);
    document.getElementById('shape').addEventListener('change', showShape);
    document.getElementById('reset').addEventListener('click', function () { resetView(); });
  }

  // Light and dark follow the system theme, in the 3D view too.
  function followTheme() {
    if (!window.matchMedia) return;
    var query = window.matchMedia('(prefers-color-scheme: dark)');
    var onChange = function () {
      if (!renderer) return;
      readColors();
      renderer.setClearColor(colors.background, 1);
      records.forEach(function (r) { styleRecord(r, r === current, !!current); });
      requestRender();
    };
    if (query.addEventListener) query.addEventListener('change', onChange);
    else if (query.addListener) query.addListener(onChange);
  }

  setupToolbar();
  timing.dom = performance.now();
  if (webglAvailable()) {
    initScene();
    timing.scene = performance.now();
    setupPicking();
    state.webgl = true;
  } else {
    var msg = document.getElementById('no-webgl');
    msg.hidden = false;
    msg.textContent = 'This browser gives no WebGL, so the 3D view is off; the list and the details work.';
  }
  followTheme();
  window.addEventListener('resize', resize);
  select(null);
  render();
  timing.drawn = performance.now();
  state.timing = timing;
  // Milliseconds from the start of navigation to a drawn page (for docs/view.md's timing).
  state.load_ms = window.performance ? performance.now() : null;
  state.ready = true;
})();
