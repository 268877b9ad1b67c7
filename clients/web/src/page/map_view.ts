// The map canvas: grid layer, scene-graph objects and relations, frontiers with their scores,
// the task's path, the robot's commanded legs (roll/fly), trail and pose, and the two-click
// path plan. Wheel zooms, drag pans, double-click fits the map again.
import type { DashboardState, Leg, Point } from "./state";

const COLOURS = { roll: "#2e9d57", fly: "#d9480f", task: "#1c7ed6", frontier: "#7048e8", robot: "#e8590c", trail: "#495057" };

export class MapView {
  private readonly context: CanvasRenderingContext2D;
  private readonly gridImage = document.createElement("canvas");
  private gridKey = "";
  private scale = 40;             // pixels per metre
  private centre: Point = { x: 0, y: 0 };
  private userMoved = false;
  private drag: { x: number; y: number; moved: boolean } | null = null;
  onClick: ((world: Point) => void) | null = null;

  constructor(private readonly canvas: HTMLCanvasElement, private readonly state: DashboardState) {
    this.context = canvas.getContext("2d")!;
    canvas.addEventListener("wheel", (e) => this.zoom(e), { passive: false });
    canvas.addEventListener("mousedown", (e) => (this.drag = { x: e.offsetX, y: e.offsetY, moved: false }));
    canvas.addEventListener("mousemove", (e) => this.pan(e));
    canvas.addEventListener("mouseup", (e) => {
      if (this.drag !== null && !this.drag.moved) this.onClick?.(this.toWorld(e.offsetX, e.offsetY));
      this.drag = null;
    });
    canvas.addEventListener("dblclick", () => (this.userMoved = false));
    new ResizeObserver(() => this.draw()).observe(canvas);
  }

  draw(): void {
    const canvas = this.canvas;
    const ratio = window.devicePixelRatio || 1;
    const width = canvas.clientWidth, height = canvas.clientHeight;
    if (canvas.width !== Math.round(width * ratio) || canvas.height !== Math.round(height * ratio)) {
      canvas.width = Math.round(width * ratio);
      canvas.height = Math.round(height * ratio);
    }
    const c = this.context;
    c.setTransform(ratio, 0, 0, ratio, 0, 0);
    c.fillStyle = "#c9ced6";
    c.fillRect(0, 0, width, height);
    if (!this.userMoved) this.fit(width, height);
    canvas.dataset.view = `${this.centre.x},${this.centre.y},${this.scale}`;  // for tests: world -> screen
    this.drawGrid(c);
    if (this.state.show.relations) this.drawRelations(c);
    if (this.state.show.frontiers) this.drawFrontiers(c);
    this.drawTaskPath(c);
    for (const leg of this.state.commandLegs) this.drawLeg(c, leg, 2.5, [6, 4]);
    this.drawPlan(c);
    if (this.state.show.objects) this.drawObjects(c);
    this.drawRobot(c);
    this.drawScaleBar(c, height);
  }

  toWorld(px: number, py: number): Point {
    const width = this.canvas.clientWidth, height = this.canvas.clientHeight;
    return { x: this.centre.x + (px - width / 2) / this.scale, y: this.centre.y - (py - height / 2) / this.scale };
  }

  private toScreen(p: Point): [number, number] {
    const width = this.canvas.clientWidth, height = this.canvas.clientHeight;
    return [width / 2 + (p.x - this.centre.x) * this.scale, height / 2 - (p.y - this.centre.y) * this.scale];
  }

  private fit(width: number, height: number): void {
    const grid = this.state.grid.grid;
    if (grid === null || width === 0) return;
    const w = grid.width * grid.resolution, h = grid.height * grid.resolution;
    const ox = grid.origin?.x ?? 0, oy = grid.origin?.y ?? 0;
    this.scale = Math.min((width - 20) / w, (height - 20) / h);
    this.centre = { x: ox + w / 2, y: oy + h / 2 };
  }

  private zoom(e: WheelEvent): void {
    e.preventDefault();
    const before = this.toWorld(e.offsetX, e.offsetY);
    this.scale = Math.min(400, Math.max(2, this.scale * Math.exp(-e.deltaY * 0.0015)));
    const after = this.toWorld(e.offsetX, e.offsetY);
    this.centre = { x: this.centre.x + before.x - after.x, y: this.centre.y + before.y - after.y };
    this.userMoved = true;
    this.draw();
  }

  private pan(e: MouseEvent): void {
    if (this.drag === null || (e.buttons & 1) === 0) return;
    const dx = e.offsetX - this.drag.x, dy = e.offsetY - this.drag.y;
    if (!this.drag.moved && Math.hypot(dx, dy) < 4) return;
    this.drag = { x: e.offsetX, y: e.offsetY, moved: true };
    this.centre = { x: this.centre.x - dx / this.scale, y: this.centre.y + dy / this.scale };
    this.userMoved = true;
    this.draw();
  }

  private drawGrid(c: CanvasRenderingContext2D): void {
    const grid = this.state.grid.grid;
    if (grid === null) return;
    const key = `${grid.revision}/${grid.width}x${grid.height}/${this.state.layer}`;
    if (key !== this.gridKey) {
      const image = this.state.grid.render(this.state.layer);
      if (image === null) return;
      this.gridImage.width = image.width;
      this.gridImage.height = image.height;
      this.gridImage.getContext("2d")!.putImageData(image, 0, 0);
      this.gridKey = key;
    }
    const ox = grid.origin?.x ?? 0, oy = grid.origin?.y ?? 0;
    const [left, top] = this.toScreen({ x: ox, y: oy + grid.height * grid.resolution });
    c.imageSmoothingEnabled = false;
    c.drawImage(this.gridImage, left, top, grid.width * grid.resolution * this.scale, grid.height * grid.resolution * this.scale);
  }

  private polyline(c: CanvasRenderingContext2D, points: Point[]): void {
    c.beginPath();
    points.forEach((p, i) => {
      const [x, y] = this.toScreen(p);
      if (i === 0) c.moveTo(x, y);
      else c.lineTo(x, y);
    });
    c.stroke();
  }

  private drawLeg(c: CanvasRenderingContext2D, leg: Leg, width: number, dash: number[] = []): void {
    c.save();
    c.strokeStyle = COLOURS[leg.mode];
    c.lineWidth = width;
    c.lineJoin = c.lineCap = "round";
    c.setLineDash(dash);
    this.polyline(c, leg.points);
    c.restore();
  }

  private drawTaskPath(c: CanvasRenderingContext2D): void {
    const path = this.state.task?.path ?? [];
    if (path.length < 2) return;
    c.save();
    c.strokeStyle = COLOURS.task;
    c.globalAlpha = 0.45;
    c.lineWidth = 8;
    c.lineJoin = c.lineCap = "round";
    this.polyline(c, path);
    c.restore();
  }

  private drawPlan(c: CanvasRenderingContext2D): void {
    const plan = this.state.plan;
    const result = plan.result;
    if (result !== null) {
      for (const segment of result.segments) {
        const points = result.path.slice(segment.first_point, segment.last_point + 1);
        this.drawLeg(c, { points, mode: segment.mode === "MOTION_MODE_FLYING" ? "fly" : "roll" }, 4);
      }
    }
    const marker = (p: Point | null, text: string) => {
      if (p === null) return;
      const [x, y] = this.toScreen(p);
      c.fillStyle = "#1d232b";
      c.beginPath();
      c.arc(x, y, 9, 0, 2 * Math.PI);
      c.fill();
      c.fillStyle = "#fff";
      c.font = "bold 11px system-ui";
      c.textAlign = "center";
      c.textBaseline = "middle";
      c.fillText(text, x, y + 0.5);
    };
    marker(plan.start, "S");
    marker(plan.goal, "G");
  }

  private drawFrontiers(c: CanvasRenderingContext2D): void {
    const best = Math.max(0, ...this.state.frontiers.map((f) => f.score?.total ?? 0));
    this.state.frontiers.forEach((frontier, index) => {
      if (frontier.centroid === null) return;
      const [x, y] = this.toScreen(frontier.centroid);
      const total = frontier.score?.total ?? 0;
      const radius = 4 + Math.min(10, Math.sqrt(frontier.size_cells) / 2);
      c.save();
      c.globalAlpha = 0.35 + 0.65 * (best > 0 ? total / best : 0);
      c.fillStyle = COLOURS.frontier;
      c.beginPath();
      c.arc(x, y, radius, 0, 2 * Math.PI);
      c.fill();
      c.restore();
      c.fillStyle = "#3b2a84";
      c.font = "11px system-ui";
      c.textAlign = "left";
      c.textBaseline = "middle";
      c.fillText(`F${index + 1} ${total.toFixed(2)}`, x + radius + 3, y);
    });
  }

  private drawObjects(c: CanvasRenderingContext2D): void {
    const target = this.state.task?.target?.object_id;
    for (const object of this.state.objects.values()) {
      if (object.position === null) continue;
      const [x, y] = this.toScreen(object.position);
      const w = Math.max(6, (object.size?.x ?? 0.3) * this.scale), h = Math.max(6, (object.size?.y ?? 0.3) * this.scale);
      const isTarget = target !== undefined && target === object.id;
      c.fillStyle = isTarget ? "#f03e3e" : "#0b7285";
      c.globalAlpha = 0.8;
      c.fillRect(x - w / 2, y - h / 2, w, h);
      c.globalAlpha = 1;
      c.font = `${isTarget ? "bold " : ""}12px system-ui`;
      c.textAlign = "center";
      c.textBaseline = "bottom";
      c.lineWidth = 3;
      c.strokeStyle = "#ffffffd0";
      const text = `${object.label} #${object.id}`;
      c.strokeText(text, x, y - h / 2 - 2);
      c.fillStyle = "#0b3d45";
      c.fillText(text, x, y - h / 2 - 2);
    }
  }

  private drawRelations(c: CanvasRenderingContext2D): void {
    c.save();
    c.strokeStyle = "#0b728580";
    c.lineWidth = 1;
    c.setLineDash([3, 3]);
    for (const relation of this.state.relations) {
      const a = this.state.objects.get(relation.subject_id)?.position;
      const b = this.state.objects.get(relation.object_id)?.position;
      if (a && b) this.polyline(c, [a, b]);
    }
    c.restore();
  }

  private drawRobot(c: CanvasRenderingContext2D): void {
    if (this.state.trail.length > 1) {
      c.save();
      c.strokeStyle = COLOURS.trail;
      c.lineWidth = 2;
      c.globalAlpha = 0.6;
      this.polyline(c, this.state.trail);
      c.restore();
    }
    const pose = this.state.pose;
    if (pose === null) return;
    const [x, y] = this.toScreen(pose);
    c.save();
    c.translate(x, y);
    c.rotate(-pose.yaw);
    c.fillStyle = COLOURS.robot;
    c.strokeStyle = "#fff";
    c.lineWidth = 2;
    c.beginPath();
    c.moveTo(12, 0);
    c.lineTo(-8, 8);
    c.lineTo(-4, 0);
    c.lineTo(-8, -8);
    c.closePath();
    c.fill();
    c.stroke();
    c.restore();
  }

  private drawScaleBar(c: CanvasRenderingContext2D, height: number): void {
    const metres = [0.5, 1, 2, 5, 10, 20].find((m) => m * this.scale >= 60) ?? 50;
    const length = metres * this.scale;
    c.fillStyle = "#1d232b";
    c.fillRect(12, height - 18, length, 3);
    c.font = "11px system-ui";
    c.textAlign = "left";
    c.textBaseline = "bottom";
    c.fillText(`${metres} m`, 12, height - 21);
  }
}
