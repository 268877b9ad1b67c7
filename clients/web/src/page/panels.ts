// The side panels: task card, plan result, frontier and scene-graph tables, event log.
import type { semnav } from "../generated/protos";
import type { ApiError } from "./api";
import type { DashboardState } from "./state";

const $ = <T extends HTMLElement>(id: string) => document.getElementById(id) as T;

function element(tag: string, text: string, className?: string): HTMLElement {
  const node = document.createElement(tag);
  node.textContent = text;
  if (className !== undefined) node.className = className;
  return node;
}

function row(cells: string[]): HTMLTableRowElement {
  const tr = document.createElement("tr");
  for (const cell of cells) tr.append(element("td", cell));
  return tr;
}

// "TASK_STATUS_RUNNING" -> "running"; an emergency stop shows as "e-stopped".
export function statusWord(state: DashboardState): string {
  const task = state.task;
  if (task === null) return state.emergencyStop ? "e-stopped" : "idle";
  const word = task.status.replace("TASK_STATUS_", "").toLowerCase();
  return word === "cancelled" && state.emergencyStop ? "e-stopped" : word;
}

export function renderTask(state: DashboardState): void {
  const task = state.task;
  const word = statusWord(state);
  const badge = $("task-status");
  badge.textContent = word;
  badge.className = `badge ${word.replace("-", "")}`;
  $("task-card").dataset.status = word;
  const estop = $<HTMLButtonElement>("estop");
  estop.classList.toggle("active", state.emergencyStop);
  estop.textContent = state.emergencyStop ? "E-STOPPED" : "EMERGENCY STOP";
  $("clear-estop").hidden = !state.emergencyStop;
  const l = state.localization;
  $("localization").textContent = l === null ? "" : l.relocalizing ? `relocalizing (${l.trigger})`
    : !l.trusted ? "pose NOT trusted" : l.recoveries > 0 ? `relocalized ×${l.recoveries}` : "";
  if (task === null) return;
  $("task-card").dataset.taskId = task.task_id;
  $("task-instruction").textContent = `“${task.instruction}”`;
  $("task-instruction").classList.remove("muted");
  $("task-progress").style.width = `${Math.round(task.progress * 100)}%`;
  const target = task.target;
  const details = [
    task.phase && `phase: ${task.phase}`,
    `progress ${Math.round(task.progress * 100)}%`,
    `re-plans ${task.replans}`,
    `exploration goals ${task.explore_goals}`,
    target && `target ${target.label || state.objects.get(target.object_id)?.label || ""} #${target.object_id} (${target.path.replace("RESOLUTION_PATH_", "").toLowerCase()} path, ${target.confidence.toFixed(2)})`,
  ].filter(Boolean);
  $("task-phase").textContent = details.join(" · ");
  const list = $("task-subgoals");
  list.replaceChildren(...task.subgoals.map((subgoal, i) => {
    const what = subgoal.type.replace("SUBGOAL_TYPE_", "").toLowerCase().replace("_", " ");
    const name = subgoal.target?.text || subgoal.target?.name || "";
    return element("li", `${what} ${name}`.trim(), i < task.current_subgoal ? "done" : i === task.current_subgoal ? "active" : "");
  }));
  $("task-reason").textContent = task.reason;
  const live = task.status === "TASK_STATUS_RUNNING" || task.status === "TASK_STATUS_PENDING";
  $<HTMLButtonElement>("task-pause").disabled = !live;
  $<HTMLButtonElement>("task-cancel").disabled = !(live || task.status === "TASK_STATUS_PAUSED");
  $<HTMLButtonElement>("task-resume").disabled = task.status !== "TASK_STATUS_PAUSED";
}

export function renderPlan(state: DashboardState, error?: ApiError): void {
  const box = $("plan-result");
  const plan = state.plan;
  if (error !== undefined) {
    const reason = error.details.find((d) => d["@type"] === "semnav.planning.v1.PlanFailureDetail")?.reason;
    box.textContent = `No path: ${error.code}${reason ? ` (${String(reason).replace("PLAN_FAILURE_REASON_", "")})` : ""} — ${error.message}`;
    box.className = "error";
    return;
  }
  box.className = "";
  const result = plan.result;
  if (result === null) {
    box.textContent = plan.start === null ? "Press “Plan path” and click a start and a goal on the map." : "Click the goal.";
    box.className = "muted";
    return;
  }
  const dl = document.createElement("dl");
  dl.className = "plan";
  dl.id = "plan-figures";
  const add = (term: string, value: string) => dl.append(element("dt", term), element("dd", value));
  add("length", `${result.length_m.toFixed(2)} m`);
  add("roll / fly", `${result.roll_m.toFixed(2)} m / ${result.fly_m.toFixed(2)} m`);
  add("energy", `${result.energy_j.toFixed(0)} J`);
  add("mode switches", String(result.mode_switches));
  add("segments", String(result.segments.length));
  add("search", `${result.expansions} expansions, ${result.planning_time_ms.toFixed(1)} ms`);
  if (result.adjustment_reason) add("goal moved", result.adjustment_reason);
  box.replaceChildren(dl);
}

export function renderFrontiers(state: DashboardState): void {
  const ranked = state.frontiers.map((f, i) => ({ f, i })).sort((a, b) => (b.f.score?.total ?? 0) - (a.f.score?.total ?? 0));
  $("frontier-count").textContent = `${state.frontiers.length}`;
  $("frontiers").querySelector("tbody")!.replaceChildren(...ranked.slice(0, 8).map(({ f, i }) => row([
    `F${i + 1}`, String(f.size_cells), f.path_distance_m < 0 ? "unreachable" : f.path_distance_m.toFixed(1),
    (f.score?.novelty ?? 0).toFixed(2), (f.score?.total ?? 0).toFixed(2),
  ])));
}

const RELATION_WORDS: Record<string, string> = {
  RELATION_KIND_NEAR: "near", RELATION_KIND_LEFT_OF: "left of", RELATION_KIND_RIGHT_OF: "right of",
  RELATION_KIND_IN_FRONT_OF: "in front of", RELATION_KIND_BEHIND: "behind", RELATION_KIND_ON: "on", RELATION_KIND_ABOVE: "above",
};

export function renderSceneGraph(state: DashboardState): void {
  const objects = [...state.objects.values()].sort((a, b) => Number(a.id) - Number(b.id));
  $("graph-count").textContent = `${objects.length} objects · ${state.relations.length} relations · rev ${state.sceneRevision}`;
  $("objects").querySelector("tbody")!.replaceChildren(...objects.map((o) => row([
    String(o.id), o.label, o.score.toFixed(2), String(o.observation_count),
    `${(o.position?.x ?? 0).toFixed(1)}, ${(o.position?.y ?? 0).toFixed(1)}`,
  ])));
  const name = (id: string) => `${state.objects.get(id)?.label ?? "?"} #${id}`;
  // Every pair is near something in a small room; the directional relations say more.
  const shown = state.relations.filter((r) => r.kind !== "RELATION_KIND_NEAR").slice(0, 40);
  $("relations").replaceChildren(...shown.map((r) =>
    element("li", `${name(r.subject_id)} ${RELATION_WORDS[r.kind] ?? r.kind} ${name(r.object_id)} (${r.distance.toFixed(1)} m)`)));
}

export function appendEvent(event: semnav.reasoning.v1.Event): void {
  const item = document.createElement("li");
  const seconds = Number(event.time?.seconds ?? 0);
  const time = document.createElement("time");
  time.textContent = new Date(seconds * 1000).toLocaleTimeString();
  item.append(time, document.createTextNode(event.message));
  item.dataset.kind = event.kind;
  if (event.task_id !== "") item.dataset.taskId = event.task_id;
  prependToLog(item);
}

// A line of the page's own in the event log (e.g. that the replay is incomplete).
export function appendNote(text: string): void {
  prependToLog(element("li", text, "muted"));
}

function prependToLog(item: HTMLElement): void {
  const list = $("events");
  list.prepend(item);
  while (list.children.length > 200) list.lastElementChild!.remove();
}
