// stereo-view's 3-D scene of the filtered cloud (three.js r111, Debian's
// libjs-three), in the left rectified frame: x right, y down, z ahead, seen
// from behind the cameras. Around the cloud, as rviz draws them: the frame's
// axes (x red, y green, z blue; 0.5 m), a grid of 1 m cells in the cameras'
// x-z plane, both cameras' frustums once the rig is known, and the plane
// stereo-cloud fitted. A click (not a drag) picks the cloud's point under
// the pointer.
"use strict";

function CloudScene(container) {
  const renderer = new THREE.WebGLRenderer({ antialias: false, preserveDrawingBuffer: true });  // throws without WebGL
  const scene = new THREE.Scene();
  scene.background = new THREE.Color(0x101010);
  const camera = new THREE.PerspectiveCamera(60, 4 / 3, 0.01, 100);
  camera.up.set(0, -1, 0);
  camera.position.set(0, -0.5, -1.5);
  const controls = new THREE.OrbitControls(camera, renderer.domElement);
  controls.target.set(0, 0, 2);
  controls.update();
  container.append(renderer.domElement);
  const render = () => renderer.render(scene, camera);
  controls.addEventListener("change", render);

  const helpers = new THREE.Group();
  const axes = new THREE.AxesHelper(0.5);
  axes.name = "axes";
  const grid = new THREE.GridHelper(10, 10, 0x666666, 0x333333);  // in its x-z plane, through the cameras
  grid.position.set(0, 0, 5);
  grid.name = "grid";
  helpers.add(axes, grid);
  scene.add(helpers);
  let frustums = null, plane = null, points = null, xyz = null, pointSize = 0.01;
  const marker = new THREE.Mesh(new THREE.SphereGeometry(1, 12, 8), new THREE.MeshBasicMaterial({ color: 0xffffff }));
  marker.visible = false;
  scene.add(marker);

  // A camera's frustum: lines from its centre (x, 0, 0) to a rectangle `depth` ahead.
  function frustum(name, x, tanX, tanY, depth, colour) {
    const corners = [[-1, -1], [1, -1], [1, 1], [-1, 1]].map(([u, v]) => [x + u * tanX * depth, v * tanY * depth, depth]);
    const vertices = [];
    corners.forEach((c, i) => vertices.push(x, 0, 0, ...c, ...c, ...corners[(i + 1) % 4]));
    const geometry = new THREE.BufferGeometry();
    geometry.setAttribute("position", new THREE.Float32BufferAttribute(vertices, 3));
    const lines = new THREE.LineSegments(geometry, new THREE.LineBasicMaterial({ color: colour }));
    lines.name = name;
    return lines;
  }

  function dispose(object) {
    object.traverse((o) => { if (o.geometry) o.geometry.dispose(); });
  }

  return {
    // The rig: the right camera `baseline` metres along x, each seeing
    // tan(half the field) tanX across and tanY down.
    setRig(baseline, tanX, tanY) {
      if (frustums) { helpers.remove(frustums); dispose(frustums); }
      frustums = new THREE.Group();
      const depth = Math.max(0.1, 2 * baseline);
      frustums.add(frustum("frustum-left", 0, tanX, tanY, depth, 0x4fc3f7),
                   frustum("frustum-right", baseline, tanX, tanY, depth, 0xffb74d));
      helpers.add(frustums);
      render();
    },
    // The plane n·p + offset = 0 (n a unit normal), as a square of side
    // `size` about the point of it nearest `near`; none for a null normal.
    setPlane(normal, offset, near, size) {
      if (plane) { helpers.remove(plane); dispose(plane); plane = null; }
      if (normal) {
        const n = new THREE.Vector3(...normal).normalize(), c = new THREE.Vector3(...near);
        c.addScaledVector(n, -(n.dot(c) + offset));
        const square = new THREE.PlaneGeometry(size, size);
        plane = new THREE.Group();
        plane.add(new THREE.Mesh(square, new THREE.MeshBasicMaterial({
                    color: 0x80deea, transparent: true, opacity: 0.18, side: THREE.DoubleSide, depthWrite: false })),
                  new THREE.LineSegments(new THREE.EdgesGeometry(square), new THREE.LineBasicMaterial({ color: 0x80deea })));
        plane.quaternion.setFromUnitVectors(new THREE.Vector3(0, 0, 1), n);
        plane.position.copy(c);
        plane.name = "plane";
        helpers.add(plane);
      }
      render();
    },
    // The points (float32 x y z) with their colours (float32 r g b, 0 to 1).
    setCloud(positions, colours, size) {
      xyz = positions;
      pointSize = size;
      const geometry = new THREE.BufferGeometry();
      geometry.setAttribute("position", new THREE.BufferAttribute(positions, 3));
      geometry.setAttribute("color", new THREE.BufferAttribute(colours, 3));
      if (points) { scene.remove(points); dispose(points); }
      points = new THREE.Points(geometry, new THREE.PointsMaterial({ size, vertexColors: THREE.VertexColors }));
      scene.add(points);
      render();
    },
    // Looks at a sphere (centre, radius) from behind the cameras, above and to the left.
    frame([cx, cy, cz], r) {
      controls.target.set(cx, cy, cz);
      camera.position.set(cx - 0.9 * r, cy - 0.8 * r, cz - 1.6 * r);
      controls.update();
    },
    // The cloud's point nearest the eye under a pixel of the canvas (CSS
    // pixels from its top-left), marked; null when there is none.
    pick(px, py) {
      if (!points) return null;
      const box = renderer.domElement.getBoundingClientRect();
      const raycaster = new THREE.Raycaster();
      raycaster.params.Points.threshold = 2 * pointSize;
      raycaster.setFromCamera(new THREE.Vector2(2 * px / box.width - 1, 1 - 2 * py / box.height), camera);
      const hits = raycaster.intersectObject(points);
      if (!hits.length) return null;
      const i = hits[0].index, point = [xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2]];
      marker.position.set(...point);
      marker.scale.setScalar(3 * pointSize);
      marker.visible = true;
      render();
      return point;
    },
    // The names of what is drawn around the cloud.
    helperNames() {
      const names = [];
      helpers.traverse((o) => { if (o.name) names.push(o.name); });
      return names;
    },
    resize() {
      const w = container.clientWidth || 480, h = container.clientHeight || 360;
      renderer.setSize(w, h, false);
      camera.aspect = w / h;
      camera.updateProjectionMatrix();
      render();
    },
    canvas: renderer.domElement,
  };
}
