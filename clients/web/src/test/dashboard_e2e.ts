// End-to-end test of the dashboard in headless Chromium against a live stack: a simulated robot
// with mapping, planning and the gateway on free loopback ports (semnav-dashboard-sim-robot
// --start-stack), the proxy, and the page. Checks that the map from the stack is drawn, that a
// typed instruction makes a task whose progress shows, that two clicks plan a path, and that
// the e-stop button stops the task and the robot, and that a page opened after a task ended shows
// that task and its events. --screenshot-dir also saves screenshots.
// Usage: node dashboard_e2e.js --bin-dir DIR --web-dir DIR [--screenshot-dir DIR [--screenshot-delay-ms MS]]
//        [--viewport WxH] [--chromium PATH] [--speed X  simulated seconds per wall second, default 1]
import { type ChildProcess, spawn } from "node:child_process";
import * as fs from "node:fs";
import * as os from "node:os";
import * as path from "node:path";
import { createRequire } from "node:module";
import * as readline from "node:readline";
import type { Page } from "playwright-core";

// playwright-core stays outside the bundle; it is loaded from the checkout's node_modules.
declare const NODE_MODULES_DIR: string;
const { chromium } = createRequire(path.join(NODE_MODULES_DIR, "resolve-from-here.js"))("playwright-core") as typeof import("playwright-core");

interface Args { binDir: string; webDir: string; screenshotDir?: string; screenshotDelayMs: string; viewport: string; chromium: string; speed: string }

function parseArgs(argv: string[]): Args {
  const get = (name: string) => {
    const i = argv.indexOf(`--${name}`);
    return i >= 0 ? argv[i + 1] : undefined;
  };
  const binDir = get("bin-dir"), webDir = get("web-dir");
  if (binDir === undefined || webDir === undefined) throw new Error("usage: dashboard_e2e.js --bin-dir DIR --web-dir DIR [--screenshot-dir DIR [--screenshot-delay-ms MS]] [--chromium PATH] [--speed X]");
  return { binDir, webDir, screenshotDir: get("screenshot-dir"), screenshotDelayMs: get("screenshot-delay-ms") ?? "3000", viewport: get("viewport") ?? "1440x900",
           chromium: get("chromium") ?? "/usr/bin/chromium", speed: get("speed") ?? "1" };
}

const children: ChildProcess[] = [];

// Starts a process and resolves with the first stdout line that parses as a JSON object.
function startJsonLine<T>(command: string, args: string[], what: string, timeoutMs: number): Promise<T> {
  const child = spawn(command, args, { stdio: ["ignore", "pipe", "pipe"] });
  children.push(child);
  let stderr = "";
  child.stderr!.on("data", (chunk) => (stderr = (stderr + chunk).slice(-4000)));
  return new Promise((resolve, reject) => {
    const timer = setTimeout(() => reject(new Error(`${what}: no start-up line within ${timeoutMs} ms\n${stderr}`)), timeoutMs);
    child.on("exit", (code) => reject(new Error(`${what} exited with ${code}\n${stderr}`)));
    readline.createInterface({ input: child.stdout! }).on("line", (line) => {
      if (!line.startsWith("{")) return;
      clearTimeout(timer);
      resolve(JSON.parse(line) as T);
    });
  });
}

function check(condition: boolean, message: string): void {
  if (!condition) throw new Error(`check failed: ${message}`);
  console.log(`ok: ${message}`);
}

async function text(page: Page, selector: string): Promise<string> {
  return (await page.textContent(selector)) ?? "";
}

async function pose(page: Page): Promise<[number, number]> {
  const value = await page.getAttribute("#map", "data-pose");
  const [x, y] = (value ?? "NaN,NaN").split(",").map(Number);
  return [x, y];
}

// Screen position (relative to the canvas) of a world point, from the view the page drew.
async function toScreen(page: Page, x: number, y: number): Promise<{ x: number; y: number }> {
  const [cx, cy, scale] = ((await page.getAttribute("#map", "data-view")) ?? "").split(",").map(Number);
  const box = (await page.locator("#map").boundingBox())!;
  return { x: box.width / 2 + (x - cx) * scale, y: box.height / 2 - (y - cy) * scale };
}

async function run(args: Args): Promise<void> {
  const started = Date.now();
  const work = fs.mkdtempSync(path.join(os.tmpdir(), "semnav-dashboard-e2e-"));
  const stack = await startJsonLine<{ gateway: string; mapping: string; planning: string; robot_id: string; nearest_object: string }>(
    path.join(args.binDir, "semnav-dashboard-sim-robot"),
    ["--start-stack", "--work-dir", path.join(work, "stack"), "--speed", args.speed], "sim robot + stack", 30000);
  const proxy = await startJsonLine<{ listen: string }>(process.execPath, [
    path.join(args.webDir, "semnav-dashboard.js"), "--listen", "127.0.0.1:0", "--gateway", stack.gateway,
    "--mapping", stack.mapping, "--planning", stack.planning, "--robot-id", stack.robot_id,
  ], "dashboard proxy", 10000);
  console.log(`stack up (gateway ${stack.gateway}), proxy on ${proxy.listen} after ${Date.now() - started} ms`);

  const context = await chromium.launchPersistentContext(path.join(work, "chromium-profile"), {
    executablePath: args.chromium,
    headless: true,
    args: ["--headless", "--no-sandbox", "--disable-gpu", "--disable-quic", "--no-first-run",
           "--disable-background-networking", "--disable-component-update", "--disable-sync"],
    viewport: { width: Number(args.viewport.split("x")[0]), height: Number(args.viewport.split("x")[1]) },
  });
  try {
    const page = context.pages()[0] ?? await context.newPage();
    const pageErrors: string[] = [];
    page.on("pageerror", (error) => pageErrors.push(error.message));
    await page.goto(`http://${proxy.listen}/`);
    check((await page.title()).includes("semnav"), "the page loads");

    // The map: cells from the running mapping service, drawn on the canvas.
    await page.waitForFunction(() => Number(document.getElementById("map")?.dataset.knownCells ?? 0) > 500, null, { timeout: 20000 });
    const known = Number(await page.getAttribute("#map", "data-known-cells"));
    const drawn = await page.evaluate(() => {
      const canvas = document.getElementById("map") as HTMLCanvasElement;
      const pixels = canvas.getContext("2d")!.getImageData(0, 0, canvas.width, canvas.height).data;
      let free = 0;  // the free-cell colour of the hierarchical layer
      for (let i = 0; i < pixels.length; i += 4) if (pixels[i] === 245 && pixels[i + 1] === 242 && pixels[i + 2] === 234) ++free;
      return free;
    });
    check(known > 500, `the map shows ${known} known cells from the stack`);
    check(drawn > 1000, `the canvas draws ${drawn} free-cell pixels`);

    // An instruction typed in becomes a running task with visible progress.
    // Exploring after the find keeps the task running until the e-stop.
    const instruction = `find a ${stack.nearest_object} then explore then look around then explore`;
    await page.fill("#instruction", instruction);
    await page.click("#instruction-form button[type=submit]");
    await page.waitForFunction(() => document.getElementById("task-card")?.dataset.status === "running", null, { timeout: 15000 });
    check((await text(page, "#task-instruction")).includes(stack.nearest_object), "the task shows the typed instruction");
    check((await page.locator("#task-subgoals li").count()) >= 2, "the task lists its subgoals");
    await page.waitForFunction(() => /phase: \w+/.test(document.getElementById("task-phase")?.textContent ?? ""), null, { timeout: 15000 });
    check(true, `task progress shows: ${await text(page, "#task-phase")}`);
    await page.waitForFunction(() => (document.getElementById("events")?.children.length ?? 0) > 0, null, { timeout: 10000 });
    check(true, `events stream in: "${await text(page, "#events li:first-child")}"`);
    const [x0, y0] = await pose(page);
    await page.waitForFunction(([x, y]) => {
      const [px, py] = (document.getElementById("map")?.dataset.pose ?? "").split(",").map(Number);
      return Math.hypot(px - x, py - y) > 0.2;
    }, [x0, y0], { timeout: 20000 });
    check(true, "the robot moves under the task");

    if (args.screenshotDir !== undefined) {
      await page.waitForTimeout(Number(args.screenshotDelayMs));
      await page.screenshot({ path: path.join(args.screenshotDir, "dashboard-mission.png") });
    }

    // The e-stop button stops the task and the robot.
    const before = await page.getAttribute("#task-card", "data-status");
    check(before === "running", `the task is still running before the e-stop (${before}: ${await text(page, "#task-reason")})`);
    await page.click("#estop");
    await page.waitForFunction(() => document.getElementById("task-card")?.dataset.status === "e-stopped", null, { timeout: 10000 });
    check(true, `after the e-stop the task shows "${await text(page, "#task-status")}"`);
    const taskId = await page.getAttribute("#task-card", "data-task-id");
    const status = await page.evaluate(async (id) => {
      const reply = await fetch("/api/operator/GetTask", { method: "POST", body: JSON.stringify({ task_id: id }) });
      return (await reply.json()).task.status as string;
    }, taskId);
    check(status === "TASK_STATUS_CANCELLED", `the gateway has the task ${status}`);
    const [sx, sy] = await pose(page);
    await page.waitForTimeout(1500);
    const [ex, ey] = await pose(page);
    check(Math.hypot(ex - sx, ey - sy) < 0.05, `the robot stays put after the e-stop (moved ${Math.hypot(ex - sx, ey - sy).toFixed(3)} m)`);

    // Two clicks plan a path: from the robot to the anchor of the farthest frontier planning can reach.
    const [rx, ry] = await pose(page);
    const anchor = await page.evaluate(async (robot) => {
      const reply = await fetch("/api/planning/ExtractFrontiers", {
        method: "POST", body: JSON.stringify({ source: { live_map: {} }, robot: { x: robot[0], y: robot[1] } }),
      });
      const frontiers = (await reply.json()).frontiers as { anchor: { x: number; y: number }; path_distance_m: number }[];
      return frontiers.filter((f) => f.path_distance_m > 0).sort((a, b) => b.path_distance_m - a.path_distance_m)[0]?.anchor;
    }, [rx, ry]);
    check(anchor !== undefined, "planning reports a reachable frontier");
    await page.click("#plan-mode");
    await page.locator("#map").click({ position: await toScreen(page, rx, ry) });
    await page.locator("#map").click({ position: await toScreen(page, anchor!.x, anchor!.y) });
    await page.waitForSelector("#plan-figures, #plan-result.error", { timeout: 15000 });
    const figures = await text(page, "#plan-result");
    check(/length\d+\.\d+ m/.test(figures) && /energy\d+ J/.test(figures) && /mode switches\d+/.test(figures),
          `two clicks plan a path: ${figures.replace(/\s+/g, " ")}`);
    if (args.screenshotDir !== undefined) await page.screenshot({ path: path.join(args.screenshotDir, "dashboard-plan.png") });

    // A task run to its end, then a fresh page: it shows that task, ended, with its events.
    await page.click("#clear-estop");
    await page.waitForFunction(() => document.getElementById("task-card")?.dataset.status === "cancelled", null, { timeout: 5000 });
    const findInstruction = `find a ${stack.nearest_object}`;
    await page.fill("#instruction", findInstruction);
    await page.click("#instruction-form button[type=submit]");
    await page.waitForFunction((previous) => document.getElementById("task-card")?.dataset.taskId !== previous, taskId, { timeout: 5000 });
    const finishedId = (await page.getAttribute("#task-card", "data-task-id"))!;
    await page.waitForFunction(() => ["succeeded", "failed", "cancelled"].includes(document.getElementById("task-card")?.dataset.status ?? ""),
                               null, { timeout: 30000 });
    const ended = await page.getAttribute("#task-card", "data-status");
    check(ended === "succeeded", `"${findInstruction}" runs to its end: ${ended} (${await text(page, "#task-reason")})`);
    const fresh = await context.newPage();
    fresh.on("pageerror", (error) => pageErrors.push(error.message));
    await page.close();
    await fresh.goto(`http://${proxy.listen}/`);
    await fresh.waitForFunction((id) => {
      const card = document.getElementById("task-card");
      return card?.dataset.taskId === id && card.dataset.status === "succeeded";
    }, finishedId, { timeout: 10000 });
    check((await text(fresh, "#task-instruction")).includes(findInstruction) && (await fresh.locator("#task-subgoals li").count()) >= 1,
          `a fresh page shows the ended task ${finishedId} "${findInstruction}" as succeeded with its subgoals`);
    // The events come after the card (a second call); the check below says what arrived.
    await fresh.waitForFunction((id) => [...document.querySelectorAll<HTMLElement>(`#events li[data-task-id="${id}"]`)]
      .some((item) => item.dataset.kind === "EVENT_KIND_TASK_STATUS" && item.textContent?.includes("TASK_STATUS_SUCCEEDED")),
                                finishedId, { timeout: 5000 }).catch(() => undefined);
    const loggedKinds = await fresh.evaluate((id) => [...document.querySelectorAll<HTMLElement>(`#events li[data-task-id="${id}"]`)]
      .map((item) => `${item.dataset.kind}: ${item.textContent ?? ""}`), finishedId);
    check(loggedKinds.some((line) => line.startsWith("EVENT_KIND_TASK_CREATED:") && line.includes(findInstruction)) &&
          loggedKinds.some((line) => line.startsWith("EVENT_KIND_TASK_STATUS:") && line.includes("TASK_STATUS_SUCCEEDED")),
          `and its ${loggedKinds.length} recorded events, from creation to success`);

    check(pageErrors.length === 0, `no page errors${pageErrors.length ? `: ${pageErrors.join("; ")}` : ""}`);
    console.log(`passed in ${((Date.now() - started) / 1000).toFixed(1)} s`);
  } finally {
    await context.close();
    fs.rmSync(work, { recursive: true, force: true });
  }
}

function stopChildren(): void {
  for (const child of children) if (child.exitCode === null) child.kill("SIGTERM");
}

run(parseArgs(process.argv.slice(2))).then(() => {
  stopChildren();
  process.exit(0);
}, (error: Error) => {
  console.error(error.message);
  stopChildren();
  process.exit(1);
});
