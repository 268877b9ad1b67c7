// Sensor frames built by hand, as a robot app would send them: a camera at (0.5, 2, 1) m looking
// along +x at a wall 3 m away, with a box 2 m away in the middle of the image detected as a
// "chair". Depth is 16-bit millimetres, little endian.
const width = 160;
const height = 120;
const intrinsics = { width, height, fx: 100, fy: 100, cx: 80, cy: 60 };
// Optical frame (x right, y down, z forward) -> map: z_opt = +x, x_opt = -y, y_opt = -z.
const cameraPose = {
  position: { x: 0.5, y: 2.0, z: 1.0 },
  orientation: { w: 0.5, x: -0.5, y: 0.5, z: -0.5 },
};
export const chairBox = { x_min: 60, y_min: 40, x_max: 100, y_max: 80 };
const wallMm = 3000;
const chairMm = 2000;

function depthImage(): Buffer {
  const data = Buffer.alloc(width * height * 2);
  for (let v = 0; v < height; ++v) {
    for (let u = 0; u < width; ++u) {
      const onChair = u >= chairBox.x_min && u < chairBox.x_max && v >= chairBox.y_min && v < chairBox.y_max;
      data.writeUInt16LE(onChair ? chairMm : wallMm, (v * width + u) * 2);
    }
  }
  return data;
}

// Frame number `index` (1, 2, ...), stamped index * 100 ms so stamps never go backwards.
export function wallFrame(index: number): object {
  const stampNs = index * 100_000_000;
  return {
    header: { robot_id: 'node-robot', frame_id: 'camera', stamp: { seconds: Math.floor(stampNs / 1e9), nanos: stampNs % 1e9 } },
    intrinsics,
    depth: { width, height, encoding: 'IMAGE_ENCODING_DEPTH_16UC1_MM', data: depthImage() },
    camera_pose: cameraPose,
    detections: [{ label: 'chair', score: 0.9, box: chairBox }],
  };
}
