// The first ten minutes, end to end: `semnav up --sim-robot` as a user starts it (here on free
// loopback ports through --config), the dashboard URL it prints opened in headless Chromium,
// "find a bed" typed into the page, and the task seen reaching SUCCEEDED there. Then the page is
// opened again after the task ended and must still show that task with its events, and SIGTERM
// stops the whole stack cleanly.
// Usage: node stack_e2e.js --bin-dir DIR [--chromium PATH] [--speed X] [--screenshot FILE]
import { type ChildProcess, spawn } from "node:child_process";
import * as fs from "node:fs";
import * as net from "node:net";
import * as os from "node:os";
import * as path from "node:path";
import { createRequire } from "node:module";
import * as readline from "node:readline";
import type { Page } from "playwright-core";

declare const NODE_MODULES_DIR: string;
let upChild: ChildProcess | undefined;  // stopped on failure too: Node does not kill its children
const { chromium } = createRequire(path.join(NODE_MODULES_DIR, "resolve-from-here.js"))("playwright-core") as typeof import("playwright-core");

interface Args { binDir: string; chromium: string; speed: string; screenshot?: string }

function parseArgs(argv: string[]): Args {
  const get = (name: string) => {
    const i = argv.indexOf(`--${name}`);
    return i >= 0 ? argv[i + 1] : undefined;
  };
  const binDir = get("bin-dir");
  if (binDir === undefined) throw new Error("usage: stack_e2e.js --bin-dir DIR [--chromium PATH] [--speed X] [--screenshot FILE]");
  return { binDir, chromium: get("chromium") ?? "/usr/bin/chromium", speed: get("speed") ?? "1", screenshot: get("screenshot") };
}

function freePort(): Promise<number> {
  return new Promise((resolve, reject) => {
    const server = net.createServer();
    server.on("error", reject);
    server.listen(0, "127.0.0.1", () => {
      const port = (server.address() as net.AddressInfo).port;
      server.close(() => resolve(port));
    });
  });
}

function check(condition: boolean, message: string): void {
  if (!condition) throw new Error(`check failed: ${message}`);
  console.log(`ok: ${message}`);
}

// deploy/local.yaml's stack on free ports, with its stores in `work`.
async function writeStack(work: string, speed: string): Promise<string> {
  const [gateway, mapping, planning, relocalization, modelproxy, dashboard] =
    await Promise.all([freePort(), freePort(), freePort(), freePort(), freePort(), freePort()]);
  const yaml = `startup_timeout_s: 30
dashboard: {listen: "127.0.0.1:${dashboard}", robot_id: sim-robot}
sim_robot: {robot_id: sim-robot, world_seed: 7, speed: ${speed}}
services:
  gateway:
    binary: semnav-gateway
    listen: "127.0.0.1:${gateway}"
    settings:
      gateway:
        mapping: {address: "127.0.0.1:${mapping}"}
        planning: {address: "127.0.0.1:${planning}", exploration_strategy: SEMANTIC_FRONTIER}
        model_proxy: {address: "127.0.0.1:${modelproxy}", deadline_ms: 5000}
  mapping:
    binary: semnav-mapping
    listen: "127.0.0.1:${mapping}"
    settings:
      mapping: {store_directory: "${path.join(work, "maps")}"}
  planning:
    binary: semnav-planning
    listen: "127.0.0.1:${planning}"
    settings:
      planning: {mapping: {address: "127.0.0.1:${mapping}"}}
  relocalization:
    binary: semnav-relocalization
    listen: "127.0.0.1:${relocalization}"
    settings:
      relocalization: {storage_dir: "${path.join(work, "landmarks")}"}
  modelproxy:
    binary: semnav-model-proxy
    listen: "127.0.0.1:${modelproxy}"
`;
  const file = path.join(work, "stack.yaml");
  fs.writeFileSync(file, yaml);
  return file;
}

// Starts `semnav up` and resolves with the dashboard URL it prints.
function startUp(binDir: string, stackFile: string, output: string[]): { child: ChildProcess; url: Promise<string> } {
  const child = spawn(path.join(binDir, "semnav"), ["up", "--sim-robot", "--config", stackFile], { stdio: ["ignore", "pipe", "pipe"] });
  upChild = child;
  child.stderr!.on("data", (chunk) => output.push(String(chunk)));
  const url = new Promise<string>((resolve, reject) => {
    const timer = setTimeout(() => reject(new Error(`no dashboard line within 60 s:\n${output.join("")}`)), 60000);
    child.on("exit", (code) => reject(new Error(`semnav up exited with ${code}:\n${output.join("")}`)));
    readline.createInterface({ input: child.stdout! }).on("line", (line) => {
      output.push(`${line}\n`);
      const match = /^dashboard: (http:\/\/\S+)$/.exec(line);
      if (match !== null) {
        clearTimeout(timer);
        resolve(match[1]);
      }
    });
  });
  return { child, url };
}

async function taskCard(page: Page): Promise<{ status: string; instruction: string; events: number }> {
  return page.evaluate(() => ({
    status: document.getElementById("task-card")?.dataset.status ?? "",
    instruction: document.getElementById("task-instruction")?.textContent ?? "",
    events: document.getElementById("events")?.children.length ?? 0,
  }));
}

async function run(args: Args): Promise<void> {
  const started = Date.now();
  const work = fs.mkdtempSync(path.join(os.tmpdir(), "semnav-stack-e2e-"));
  const output: string[] = [];
  const up = startUp(args.binDir, await writeStack(work, args.speed), output);
  const context = await chromium.launchPersistentContext(path.join(work, "chromium-profile"), {
    executablePath: args.chromium,
    headless: true,
    args: ["--headless", "--no-sandbox", "--disable-gpu", "--disable-quic", "--no-first-run",
           "--disable-background-networking", "--disable-component-update", "--disable-sync"],
    viewport: { width: 1440, height: 900 },
  });
  try {
    const url = await up.url;
    check(true, `semnav up printed the dashboard URL ${url} after ${Date.now() - started} ms`);
    const page = context.pages()[0] ?? await context.newPage();
    const pageErrors: string[] = [];
    page.on("pageerror", (error) => pageErrors.push(error.message));
    await page.goto(url);
    check((await page.title()).includes("semnav"), "the page loads");
    await page.waitForFunction(() => Number(document.getElementById("map")?.dataset.knownCells ?? 0) > 500, null, { timeout: 30000 });
    check(true, "the simulated robot's map is on the page");

    await page.fill("#instruction", "find a bed");
    await page.click("#instruction-form button[type=submit]");
    await page.waitForFunction(() => document.getElementById("task-card")?.dataset.status === "running", null, { timeout: 15000 });
    check(true, "the typed instruction runs as a task");
    if (args.screenshot !== undefined) {
      await page.waitForTimeout(20000);
      await page.screenshot({ path: args.screenshot });
    }
    await page.waitForFunction(() => ["succeeded", "failed", "cancelled"].includes(document.getElementById("task-card")?.dataset.status ?? ""),
                               null, { timeout: 240000 });
    const ended = await taskCard(page);
    const reason = ended.status === "succeeded" ? "" : `: ${(await page.textContent("#task-reason")) ?? ""}; events: ${(await page.textContent("#events")) ?? ""}`;
    check(ended.status === "succeeded", `the robot found the bed: the task shows "${ended.status}" after ${((Date.now() - started) / 1000).toFixed(0)} s${reason}`);

    // A page opened after the task ended knows what happened.
    const fresh = await context.newPage();
    fresh.on("pageerror", (error) => pageErrors.push(error.message));
    await fresh.goto(url);
    await fresh.waitForFunction(() => document.getElementById("task-card")?.dataset.status === "succeeded", null, { timeout: 15000 });
    await fresh.waitForFunction(() => (document.getElementById("events")?.children.length ?? 0) > 0, null, { timeout: 15000 });
    const reopened = await taskCard(fresh);
    check(reopened.instruction.includes("find a bed"), `a page opened after the end shows the task "${reopened.instruction}"`);
    check(reopened.events > 0, `and its ${reopened.events} events`);
    await page.reload();
    await page.waitForFunction(() => document.getElementById("task-card")?.dataset.status === "succeeded", null, { timeout: 15000 });
    check(true, "a reloaded page shows the ended task too");
    check(pageErrors.length === 0, `no page errors${pageErrors.length ? `: ${pageErrors.join("; ")}` : ""}`);
  } catch (error) {
    console.error(`semnav up said:\n${output.join("").slice(-6000)}`);
    throw error;
  } finally {
    await context.close();
  }
  const exited = new Promise<number | null>((resolve) => up.child.on("exit", (code) => resolve(code)));
  up.child.kill("SIGTERM");
  const code = await exited;
  // The launcher names the service that did not stop cleanly; without its words a red run
  // cannot be read (seen once beside the fuzz tests).
  if (code !== 0) console.error(`semnav up said after SIGTERM:\n${output.join("").slice(-6000)}`);
  check(code === 0, `SIGTERM stops the stack cleanly (exit ${code})`);
  fs.rmSync(work, { recursive: true, force: true });
  console.log(`passed in ${((Date.now() - started) / 1000).toFixed(1)} s`);
}

run(parseArgs(process.argv.slice(2))).then(() => process.exit(0), (error: Error) => {
  console.error(error.message);
  if (upChild !== undefined && upChild.exitCode === null) upChild.kill("SIGTERM");
  process.exit(1);
});
