// Wires the proxy's streams and calls to the state, the map and the panels.
import type { semnav } from "../generated/protos";
import { call, CallError, requestId, StreamHub } from "./api";
import { MapView } from "./map_view";
import { appendEvent, appendNote, renderFrontiers, renderPlan, renderSceneGraph, renderTask } from "./panels";
import { DashboardState, type Point } from "./state";


const $ = <T extends HTMLElement>(id: string) => document.getElementById(id) as T;
const state = new DashboardState();
const streams = new StreamHub();
const map = new MapView($<HTMLCanvasElement>("map"), state);
let frame = 0;
// Redraw at most once per animation frame however many messages arrive.
function redraw(): void {
  if (frame !== 0) return;
  frame = requestAnimationFrame(() => {
    frame = 0;
    map.draw();
    const grid = state.grid.grid;
    const known = state.grid.knownCells();
    const canvas = $("map");
    canvas.dataset.knownCells = String(known);
    canvas.dataset.revision = state.grid.revision;
    if (state.pose !== null) canvas.dataset.pose = `${state.pose.x.toFixed(3)},${state.pose.y.toFixed(3)}`;
    $("map-info").textContent = grid === null ? "waiting for the map…"
      : `${grid.width}×${grid.height} cells @ ${grid.resolution.toFixed(2)} m · ${known} known · rev ${grid.revision}`;
  });
}

// One status light per stream in the header.
function link(name: string): (connected: boolean) => void {
  const light = document.createElement("span");
  light.className = "link";
  light.textContent = name;
  $("links").append(light);
  return (connected) => {
    light.className = `link ${connected ? "up" : "down"}`;
  };
}

function watchMap(): void {
  streams.subscribe<semnav.mapping.v1.WatchGridMapResponse>("grid", {
    service: "mapping", method: "WatchGridMap",
    request: () => ({ since_revision: state.grid.revision, min_interval_ms: 500 }),
    onMessage: (update) => {
      state.grid.apply(update);
      redraw();
    },
    onStatus: link("map"),
  });
  streams.subscribe<semnav.mapping.v1.WatchSceneGraphResponse>("scene", {
    service: "mapping", method: "WatchSceneGraph",
    request: () => ({ since_revision: state.sceneRevision }),
    onMessage: (update) => {
      state.applySceneGraph(update);
      renderSceneGraph(state);
      redraw();
    },
    onStatus: link("scene graph"),
  });
}

function watchRobot(): void {
  streams.subscribe<semnav.reasoning.v1.StreamFastTelemetryResponse>("fast", {
    service: "operator", method: "StreamFastTelemetry",
    request: () => ({ robot_id: state.robotId, max_rate_hz: 10 }),
    onMessage: (sample) => {
      state.applyFastTelemetry(sample);
      if (sample.task_id !== "" && sample.task_id !== state.task?.task_id) watchTask(sample.task_id);
      redraw();
    },
    onStatus: link("robot"),
  });
  streams.subscribe<semnav.reasoning.v1.StreamSlowTelemetryResponse>("slow", {
    service: "operator", method: "StreamSlowTelemetry",
    request: () => ({ robot_id: state.robotId, period: { seconds: 1 } }),
    onMessage: (sample) => {
      state.emergencyStop = sample.emergency_stop_active;
      if (sample.localization) state.localization = sample.localization;
      $("robot-id").textContent = `${state.robotId}${sample.session_connected ? "" : " (offline)"}`;
      renderTask(state);
    },
    onStatus: link("gateway"),
  });
}

// The live event log, after event `lastEvent` ("0": only what happens from now on).
function watchEvents(lastEvent: string, onStatus: (connected: boolean) => void): void {
  streams.subscribe<semnav.reasoning.v1.StreamEventsResponse>("events", {
    service: "operator", method: "StreamEvents",
    request: () => ({ robot_id: "", last_event_id: lastEvent }),
    onMessage: (message) => {
      if (message.event === null) return;
      lastEvent = message.event.event_id;
      appendEvent(message.event);
    },
    onStatus,
  });
}

// One task is watched at a time: the latest submitted or the one the robot reports.
let watchedTask = "";
function watchTask(taskId: string): void {
  if (watchedTask === taskId) return;
  watchedTask = taskId;
  let revision = "0";
  streams.subscribe<semnav.reasoning.v1.WatchTaskResponse>("task", {
    service: "operator", method: "WatchTask",
    request: () => ({ task_id: taskId, since_revision: revision }),
    onMessage: (message) => {
      if (message.task === null) return;
      revision = message.task.revision;
      state.task = message.task;
      renderTask(state);
      redraw();
    },
  });
}

// What happened before the page opened: the robot's latest task, running or ended, goes on the
// card and its recorded events into the log, as if the page had been open during it; the live
// log then continues from the gateway's newest event. Resolves with that event's id.
async function loadLatestTask(): Promise<string> {
  const { tasks } = await call<semnav.reasoning.v1.ListTasksResponse>("operator", "ListTasks", { robot_id: state.robotId });
  const latest = tasks[tasks.length - 1];
  if (latest === undefined) return "0";
  // A task the page already follows (submitted or reported by telemetry meanwhile) is newer.
  if (watchedTask === "") {
    state.task = latest;
    renderTask(state);
    watchTask(latest.task_id);
  }
  const log = await call<semnav.reasoning.v1.ListEventsResponse>("operator", "ListEvents", { task_id: latest.task_id });
  if (log.truncated) appendNote("earlier events of this task were dropped from the gateway's log");
  for (const event of log.events) appendEvent(event);
  return log.last_event_id;
}

// Until the gateway answers (it may start after the page), the log waits: live events before
// the replayed ones would be out of order.
async function showHistoryThenLiveEvents(): Promise<void> {
  const status = link("events");
  for (let retryMs = 500; ; retryMs = Math.min(retryMs * 2, 5000)) {
    try {
      watchEvents(await loadLatestTask(), status);
      return;
    } catch (error) {
      // A gateway without ListEvents (older than the page) still streams live events.
      if (error instanceof CallError && error.body.code === "UNIMPLEMENTED") {
        watchEvents("0", status);
        return;
      }
      await new Promise((resolve) => setTimeout(resolve, retryMs));
    }
  }
}

async function refreshFrontiers(): Promise<void> {
  if (state.pose === null || state.grid.grid === null) return;
  try {
    const reply = await call<semnav.planning.v1.ExtractFrontiersResponse>("planning", "ExtractFrontiers", {
      source: { live_map: {} }, robot: { x: state.pose.x, y: state.pose.y, yaw: state.pose.yaw },
    }, 5000);
    state.frontiers = reply.frontiers;
  } catch {
    state.frontiers = [];  // e.g. the robot outside the explored grid yet
  }
  renderFrontiers(state);
  redraw();
}

async function planBetween(start: Point, goal: Point): Promise<void> {
  try {
    state.plan.result = await call<semnav.planning.v1.PlanPathResponse>("planning", "PlanPath", {
      source: { live_map: {} }, start, goal, planner: $<HTMLSelectElement>("planner").value,
      goal_tolerance_m: 0.5, robot_radius_m: 0.2,
    }, 10000);
    renderPlan(state);
  } catch (error) {
    state.plan.result = null;
    renderPlan(state, error instanceof CallError ? error.body : { code: "UNAVAILABLE", message: String(error), details: [] });
  }
  redraw();
}

function wireControls(): void {
  $("instruction-form").addEventListener("submit", async (e) => {
    e.preventDefault();
    const input = $<HTMLInputElement>("instruction");
    const errorBox = $("instruction-error");
    errorBox.textContent = "";
    try {
      const reply = await call<semnav.reasoning.v1.SubmitInstructionResponse>("operator", "SubmitInstruction", {
        request_id: requestId(), robot_id: state.robotId, instruction: input.value,
      });
      state.task = reply.task;
      state.plan = { start: null, goal: null, result: null };
      renderTask(state);
      watchTask(reply.task_id);
    } catch (error) {
      errorBox.textContent = error instanceof Error ? error.message : String(error);
    }
  });
  // A control that fails says so in the header: an e-stop must never fail silently.
  const guarded = (what: string, action: () => Promise<void>) => async () => {
    const box = $("control-error");
    box.textContent = "";
    try {
      await action();
    } catch (error) {
      box.textContent = `${what} failed: ${error instanceof Error ? error.message : String(error)}`;
    }
  };
  $("estop").addEventListener("click", guarded("Emergency stop", async () => {
    await call("operator", "EmergencyStop", { request_id: requestId(), robot_id: state.robotId, reason: "dashboard emergency stop" }, 3000);
    state.emergencyStop = true;
    renderTask(state);
  }));
  $("relocalize").addEventListener("click", guarded("Relocalization", async () => {
    const reply = await call<{ localization: semnav.reasoning.v1.RobotLocalization | null }>("operator", "RelocalizeRobot",
      { request_id: requestId(), robot_id: state.robotId, reason: "operator (dashboard)" });
    state.localization = reply.localization;
    renderTask(state);
  }));
  $("clear-estop").addEventListener("click", guarded("Clearing the e-stop", async () => {
    await call("operator", "ClearEmergencyStop", { request_id: requestId(), robot_id: state.robotId });
    state.emergencyStop = false;
    renderTask(state);
  }));
  const control = (method: string) => guarded(method.replace("Task", ""), async () => {
    if (state.task === null) return;
    const reply = await call<{ task: semnav.reasoning.v1.TaskSnapshot | null }>("operator", method,
      { request_id: requestId(), task_id: state.task.task_id, reason: "operator (dashboard)" });
    if (reply.task !== null) state.task = reply.task;
    renderTask(state);
  });
  $("task-pause").addEventListener("click", control("PauseTask"));
  $("task-resume").addEventListener("click", control("ResumeTask"));
  $("task-cancel").addEventListener("click", control("CancelTask"));

  const planButton = $("plan-mode");
  let planning = false;
  planButton.addEventListener("click", () => {
    planning = !planning;
    planButton.classList.toggle("active", planning);
    state.plan = { start: null, goal: null, result: null };
    renderPlan(state);
    redraw();
  });
  map.onClick = (point) => {
    if (!planning) return;
    if (state.plan.start === null || state.plan.goal !== null) {
      state.plan = { start: point, goal: null, result: null };
      renderPlan(state);
    } else {
      state.plan.goal = point;
      void planBetween(state.plan.start, point);
    }
    redraw();
  };
  $<HTMLSelectElement>("layer").addEventListener("change", (e) => {
    state.layer = (e.target as HTMLSelectElement).value as typeof state.layer;
    redraw();
  });
  for (const name of ["frontiers", "objects", "relations"] as const) {
    $<HTMLInputElement>(`show-${name}`).addEventListener("change", (e) => {
      state.show[name] = (e.target as HTMLInputElement).checked;
      redraw();
    });
  }
}

async function start(): Promise<void> {
  const config = await (await fetch("/api/config")).json() as { robot_id: string };
  state.robotId = new URLSearchParams(location.search).get("robot") ?? config.robot_id;
  $("robot-id").textContent = state.robotId;
  wireControls();
  watchMap();
  watchRobot();
  void showHistoryThenLiveEvents();
  setInterval(() => void refreshFrontiers(), 2000);
  renderTask(state);
  renderPlan(state);
  redraw();
}

void start();
