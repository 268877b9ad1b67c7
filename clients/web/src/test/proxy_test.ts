// The proxy against a gRPC server of its own (grpc-js, same protos) that records what arrives:
// the JSON mapping, token and deadline pass-through, error codes and typed details, single and
// multiplexed server-sent event streams, cancellation when the browser leaves, upstream TLS, and
// the command line. Usage: node proxy_test.js --web-dir DIR
import { type ChildProcess, execFileSync, spawn } from "node:child_process";
import * as fs from "node:fs";
import * as os from "node:os";
import * as path from "node:path";
import * as readline from "node:readline";
import * as grpc from "@grpc/grpc-js";
import * as protobuf from "protobufjs";
import { loadPackages } from "../server/upstreams";

declare const DEFAULT_PROTO_DIR: string;

const webDir = process.argv[process.argv.indexOf("--web-dir") + 1];
const proxyScript = path.join(webDir, "semnav-dashboard.js");
const children: ChildProcess[] = [];
let failures = 0;

function check(condition: boolean, message: string): void {
  console.log(`${condition ? "ok" : "FAILED"}: ${message}`);
  if (!condition) ++failures;
}

interface Seen { authorization?: string; deadlineMs?: number; cancelled?: boolean }

// OperatorService with GetTask, WatchTask and StreamEvents; "missing" ids are NOT_FOUND with an
// ErrorInfo detail naming task_id, as the gateway sends them.
function upstreamServer(seen: Seen[]): grpc.Server {
  const root = new protobuf.Root();
  root.resolvePath = (origin, target) => {
    const local = path.join(DEFAULT_PROTO_DIR, target);
    return fs.existsSync(local) ? local : protobuf.util.path.resolve(origin, target);
  };
  root.loadSync("semnav/common/v1/errors.proto", { keepCase: true });
  const errorInfo = root.lookupType("semnav.common.v1.ErrorInfo");
  const richStatus = root.lookupType("semnav.common.v1.RichStatus");
  const notFound = (): Partial<grpc.StatusObject> => {
    const metadata = new grpc.Metadata();
    const detail = errorInfo.encode({ reason: "NOT_FOUND", field: "task_id" }).finish();
    metadata.set("grpc-status-details-bin", Buffer.from(richStatus.encode({
      code: grpc.status.NOT_FOUND, message: "task_id: no task 'missing'",
      details: [{ type_url: "type.googleapis.com/semnav.common.v1.ErrorInfo", value: detail }],
    }).finish()));
    return { code: grpc.status.NOT_FOUND, details: "task_id: no task 'missing'", metadata };
  };
  const record = (call: grpc.ServerUnaryCall<object, object> | grpc.ServerWritableStream<object, object>) => {
    const deadline = call.getDeadline();
    const entry: Seen = {
      authorization: call.metadata.get("authorization")[0] as string | undefined,
      deadlineMs: Number.isFinite(Number(deadline)) ? Number(deadline) - Date.now() : undefined,  // Date or epoch ms
    };
    seen.push(entry);
    return entry;
  };
  const snapshot = (taskId: string, revision: string) => ({
    task_id: taskId, robot_id: "r1", status: "TASK_STATUS_RUNNING", revision, progress: 0.5,
  });
  const server = new grpc.Server();
  const packages = loadPackages(DEFAULT_PROTO_DIR);
  server.addService(packages["semnav.reasoning.v1.OperatorService"] as grpc.ServiceDefinition, {
    GetTask: (call: grpc.ServerUnaryCall<{ task_id: string }, object>, done: grpc.sendUnaryData<object>) => {
      record(call);
      if (call.request.task_id === "missing") done(notFound());
      else done(null, { task: snapshot(call.request.task_id, "9007199254740993") });
    },
    WatchTask: (call: grpc.ServerWritableStream<{ task_id: string }, object>) => {
      record(call);
      if (call.request.task_id === "missing") {
        call.emit("error", notFound());
        return;
      }
      call.write({ task: snapshot(call.request.task_id, "1") });
      call.write({ task: { ...snapshot(call.request.task_id, "2"), status: "TASK_STATUS_SUCCEEDED" } });
      call.end();
    },
    StreamEvents: (call: grpc.ServerWritableStream<{ last_event_id: string }, object>) => {
      const entry = record(call);
      call.on("cancelled", () => (entry.cancelled = true));
      call.write({ event: { event_id: "1", kind: "EVENT_KIND_SESSION", message: "robot connected" } });
      if (call.request.last_event_id === "0") call.write({ event: { event_id: "2", kind: "EVENT_KIND_TASK_CREATED", message: "task t1" } });
      else call.end();  // "7": two messages then end; "0": stays open until cancelled
    },
  });
  return server;
}

function bind(server: grpc.Server, credentials: grpc.ServerCredentials): Promise<number> {
  return new Promise((resolve, reject) => server.bindAsync("127.0.0.1:0", credentials, (e, port) => (e ? reject(e) : resolve(port))));
}

function startProxy(args: string[], env: NodeJS.ProcessEnv = {}): Promise<string> {
  const child = spawn(process.execPath, [proxyScript, "--listen", "127.0.0.1:0", ...args], {
    stdio: ["ignore", "pipe", "pipe"], env: { ...process.env, ...env },
  });
  children.push(child);
  return new Promise((resolve, reject) => {
    child.on("exit", (code) => reject(new Error(`proxy exited with ${code}`)));
    readline.createInterface({ input: child.stdout! }).on("line", (line) => resolve(`http://${JSON.parse(line).listen}`));
  });
}

async function post(base: string, api: string, body: unknown, headers: Record<string, string> = {}) {
  const reply = await fetch(`${base}${api}`, { method: "POST", headers, body: typeof body === "string" ? body : JSON.stringify(body) });
  return { status: reply.status, type: reply.headers.get("content-type") ?? "", text: await reply.text() };
}

function events(text: string): { event: string; data: Record<string, unknown> }[] {
  return text.split("\n\n").filter((b) => b.startsWith("event: ")).map((block) => {
    const [head, data] = block.split("\n");
    return { event: head.slice(7), data: JSON.parse(data.slice(6)) };
  });
}

async function run(): Promise<void> {
  const help = execFileSync(process.execPath, [proxyScript, "--help"], { encoding: "utf8" });
  check(help.includes("--gateway ADDR") && help.includes("--tls-ca FILE"), "--help lists the flags");
  let code = 0;
  try {
    execFileSync(process.execPath, [proxyScript, "--bogus"], { stdio: "pipe" });
  } catch (error) {
    code = (error as { status: number }).status;
  }
  check(code === 2, `an unknown flag exits with 2 (got ${code})`);

  const seen: Seen[] = [];
  const server = upstreamServer(seen);
  const port = await bind(server, grpc.ServerCredentials.createInsecure());
  const upstream = `127.0.0.1:${port}`;
  const base = await startProxy(["--gateway", upstream, "--mapping", upstream, "--planning", upstream, "--deadline-ms", "7000",
                                 "--token-env", "TEST_UPSTREAM_TOKEN"], { TEST_UPSTREAM_TOKEN: "from-env" });

  let reply = await post(base, "/api/operator/GetTask", { task_id: "t1" }, { authorization: "Bearer abc", "grpc-timeout": "1500m" });
  const task = JSON.parse(reply.text).task;
  check(reply.status === 200 && task.task_id === "t1" && task.status === "TASK_STATUS_RUNNING",
        "a unary call returns the response as JSON with enum names");
  check(task.revision === "9007199254740993" && task.instruction === "", "64-bit integers are strings; unset fields present");
  check(seen[0].authorization === "Bearer abc", "the Authorization header reaches the upstream");
  check(seen[0].deadlineMs! > 1000 && seen[0].deadlineMs! <= 1500, `grpc-timeout 1500m becomes the deadline (${seen[0].deadlineMs} ms left)`);
  await post(base, "/api/operator/GetTask?timeout_ms=2500", { task_id: "t1" });
  check(seen[1].deadlineMs! > 2000 && seen[1].deadlineMs! <= 2500, `timeout_ms=2500 becomes the deadline (${seen[1].deadlineMs} ms left)`);
  check(seen[1].authorization === "Bearer from-env", "without a header the --token-env token is sent");
  await post(base, "/api/operator/GetTask", { task_id: "t1" });
  check(seen[2].deadlineMs! > 6000 && seen[2].deadlineMs! <= 7000, `unary calls default to --deadline-ms (${seen[2].deadlineMs} ms left)`);

  reply = await post(base, "/api/operator/GetTask", { task_id: "missing" });
  const error = JSON.parse(reply.text);
  check(reply.status === 404 && error.code === "NOT_FOUND" && error.message.includes("missing"), "NOT_FOUND maps to HTTP 404 with its message");
  check(error.details[0]?.["@type"] === "semnav.common.v1.ErrorInfo" && error.details[0]?.field === "task_id",
        "the typed ErrorInfo detail is decoded and names the field");

  reply = await post(base, "/api/operator/StreamEvents", { last_event_id: "7" });
  let stream = events(reply.text);
  check(reply.type.startsWith("text/event-stream") && stream.length === 2 && stream[0].event === "message" &&
        (stream[0].data.event as { message: string }).message === "robot connected" && stream[1].event === "end",
        "a server stream becomes SSE message events and one end event");
  const get = await fetch(`${base}/api/operator/WatchTask?request=${encodeURIComponent(JSON.stringify({ task_id: "t1" }))}`);
  stream = events(await get.text());
  check(stream.map((e) => e.event).join(",") === "message,message,end", "GET with ?request= streams too (EventSource)");
  reply = await post(base, "/api/operator/WatchTask", { task_id: "missing" });
  stream = events(reply.text);
  check(stream.length === 1 && stream[0].event === "error" && stream[0].data.code === "NOT_FOUND", "a failed stream ends with an error event");

  reply = await post(base, "/api/streams", {
    task: { service: "operator", method: "WatchTask", request: { task_id: "t2" } },
    log: { service: "operator", method: "StreamEvents", request: { last_event_id: "7" } },
  });
  stream = events(reply.text);
  const of = (name: string) => stream.filter((e) => e.data.stream === name).map((e) => e.event).join(",");
  check(of("task") === "message,message,end" && of("log") === "message,end", "/api/streams multiplexes named streams and ends after all");
  reply = await post(base, "/api/streams", { x: { service: "operator", method: "GetTask", request: {} } });
  check(reply.status === 400 && reply.text.includes("x: no server-streaming method"), "/api/streams refuses a unary method");

  const abort = new AbortController();
  const open = await fetch(`${base}/api/operator/StreamEvents`, { method: "POST", body: "{\"last_event_id\":\"0\"}", signal: abort.signal });
  const reader = open.body!.getReader();
  await reader.read();
  const watcher = seen[seen.length - 1];
  abort.abort();
  for (let i = 0; i < 40 && !watcher.cancelled; ++i) await new Promise((r) => setTimeout(r, 50));
  check(watcher.cancelled === true, "closing the browser's stream cancels the upstream call");

  reply = await post(base, "/api/operator/GetTask", "{not json");
  check(reply.status === 400 && JSON.parse(reply.text).code === "INVALID_ARGUMENT", "bad JSON is INVALID_ARGUMENT (400)");
  reply = await post(base, "/api/operator/GetTask", {}, { "grpc-timeout": "soon" });
  check(reply.status === 400 && reply.text.includes("grpc-timeout"), "a bad grpc-timeout is refused naming the header");
  reply = await post(base, "/api/operator/NoSuchMethod", {});
  check(reply.status === 404, "an unknown method is 404");
  reply = await post(base, "/api/mapping/GetSceneGraph", {});
  check(reply.status === 501 && JSON.parse(reply.text).code === "UNIMPLEMENTED", "the upstream's UNIMPLEMENTED maps to 501");
  const page = await fetch(`${base}/`);
  check(page.status === 200 && (await page.text()).includes("<canvas id=\"map\">"), "the page is served at /");
  check((await fetch(`${base}/../../etc/passwd`)).status !== 200, "paths outside the page folder are not served");

  // Upstream TLS: a server certificate for localhost, verified with --tls-ca.
  const dir = fs.mkdtempSync(path.join(os.tmpdir(), "semnav-proxy-test-"));
  try {
    execFileSync("openssl", ["req", "-x509", "-newkey", "rsa:2048", "-nodes", "-days", "1", "-subj", "/CN=localhost",
      "-addext", "subjectAltName=DNS:localhost", "-keyout", path.join(dir, "key.pem"), "-out", path.join(dir, "cert.pem")], { stdio: "ignore" });
    const tlsServer = upstreamServer([]);
    const cert = fs.readFileSync(path.join(dir, "cert.pem"));
    const tlsPort = await bind(tlsServer, grpc.ServerCredentials.createSsl(null, [{ private_key: fs.readFileSync(path.join(dir, "key.pem")), cert_chain: cert }]));
    const tlsBase = await startProxy(["--gateway", `127.0.0.1:${tlsPort}`, "--tls-ca", path.join(dir, "cert.pem"), "--tls-server-name", "localhost"]);
    reply = await post(tlsBase, "/api/operator/GetTask", { task_id: "t1" });
    check(reply.status === 200, "with --tls-ca the proxy calls a TLS upstream");
    const plainBase = await startProxy(["--gateway", `127.0.0.1:${tlsPort}`]);
    reply = await post(plainBase, "/api/operator/GetTask", { task_id: "t1" }, { "grpc-timeout": "2S" });
    check(reply.status === 503 || reply.status === 504, `without it the TLS upstream is unreachable (${reply.status})`);
    tlsServer.forceShutdown();
  } finally {
    fs.rmSync(dir, { recursive: true, force: true });
  }
  server.forceShutdown();
}

run().catch((error: Error) => {
  console.error(error.stack);
  ++failures;
}).finally(() => {
  for (const child of children) child.kill("SIGTERM");
  console.log(failures === 0 ? "all passed" : `${failures} failed`);
  process.exit(failures === 0 ? 0 : 1);
});
