// Everything the page shows, fed by the streams and calls in main.ts and drawn by the views.
import type { semnav } from "../generated/protos";
import { LiveGrid } from "./grid";

export type Point = { x: number; y: number };
export type Mode = "roll" | "fly";
export type Leg = { points: Point[]; mode: Mode };

export interface PlanState {
  start: Point | null;
  goal: Point | null;
  result: semnav.planning.v1.PlanPathResponse | null;
}

export class DashboardState {
  robotId = "";
  grid = new LiveGrid();
  layer: semnav.common.v1.GridLayerKind = "GRID_LAYER_KIND_HIERARCHICAL";
  pose: (Point & { yaw: number }) | null = null;
  trail: Point[] = [];
  commandLegs: Leg[] = [];  // the navigate command the robot is executing, by mode
  task: semnav.reasoning.v1.TaskSnapshot | null = null;
  emergencyStop = false;
  localization: semnav.reasoning.v1.RobotLocalization | null = null;
  frontiers: semnav.planning.v1.Frontier[] = [];
  objects = new Map<string, semnav.mapping.v1.SceneObject>();
  relations: semnav.mapping.v1.Relation[] = [];
  sceneRevision = "0";
  plan: PlanState = { start: null, goal: null, result: null };
  show = { frontiers: true, objects: true, relations: false };

  applySceneGraph(update: semnav.mapping.v1.WatchSceneGraphResponse): void {
    if (update.snapshot) {
      this.objects = new Map(update.snapshot.objects.map((o) => [o.id, o]));
      this.relations = update.snapshot.relations;
      this.sceneRevision = update.snapshot.revision;
    } else if (update.delta) {
      for (const id of update.delta.removed_object_ids) this.objects.delete(id);
      for (const o of update.delta.upserted_objects) this.objects.set(o.id, o);
      this.relations = update.delta.relations;
      this.sceneRevision = update.delta.revision;
    }
  }

  applyFastTelemetry(sample: semnav.reasoning.v1.StreamFastTelemetryResponse): void {
    // The gateway's map pose (its map -> odom correction applied); the robot's own pose from
    // gateways without the relocalization loop.
    if (sample.localization) this.localization = sample.localization;
    const pose = sample.localization?.map_pose ?? sample.state?.pose;
    if (pose?.position && pose.orientation) {
      const q = pose.orientation;
      const yaw = Math.atan2(2 * (q.w * q.z + q.x * q.y), 1 - 2 * (q.y * q.y + q.z * q.z));
      const point = { x: pose.position.x, y: pose.position.y };
      const last = this.trail[this.trail.length - 1];
      if (last === undefined || Math.hypot(last.x - point.x, last.y - point.y) > 0.05) this.trail.push(point);
      if (this.trail.length > 5000) this.trail.splice(0, this.trail.length - 5000);
      this.pose = { ...point, yaw };
    }
    const navigate = sample.last_command?.navigate;
    // Navigate paths are in the robot's odometry frame: into the map frame for drawing.
    const path = navigate ? navigate.path.map((w) => ({ ...w, position: toMap(sample.localization?.map_from_odom, w.position) })) : [];
    this.commandLegs = navigate && this.pose ? legs(this.pose, path) : [];
  }
}

// Consecutive waypoints of one mode joined into legs; a waypoint's mode is that of the segment
// ending at it (UNSPECIFIED keeps the previous mode).
function legs(from: Point, path: semnav.reasoning.v1.PathWaypoint[]): Leg[] {
  const result: Leg[] = [];
  let previous: Point = from;
  let mode: Mode = "roll";
  for (const waypoint of path) {
    if (waypoint.position === null) continue;
    if (waypoint.mode === "LOCOMOTION_MODE_AIR") mode = "fly";
    else if (waypoint.mode === "LOCOMOTION_MODE_GROUND") mode = "roll";
    const point = { x: waypoint.position.x, y: waypoint.position.y };
    const current = result[result.length - 1];
    if (current !== undefined && current.mode === mode) current.points.push(point);
    else result.push({ points: [previous, point], mode });
    previous = point;
  }
  return result;
}

// A point of the robot's odometry frame in the map frame (planar map_from_odom; unset = identity).
function toMap(t: semnav.common.v1.Pose | null | undefined, p: semnav.common.v1.Vector3 | null): semnav.common.v1.Vector3 | null {
  if (!t?.position || !t.orientation || p === null) return p;
  const q = t.orientation;
  const yaw = Math.atan2(2 * (q.w * q.z + q.x * q.y), 1 - 2 * (q.y * q.y + q.z * q.z));
  const c = Math.cos(yaw);
  const s = Math.sin(yaw);
  return { x: c * p.x - s * p.y + t.position.x, y: s * p.x + c * p.y + t.position.y, z: p.z + t.position.z };
}
