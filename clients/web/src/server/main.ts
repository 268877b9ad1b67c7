// semnav-dashboard: serves the ground-station page and transcodes its HTTP/JSON + SSE calls to
// the gateway's OperatorService and to mapping and planning (schema from the .proto files).
import * as http from "node:http";
import * as path from "node:path";
import { parseConfig, usage, type ProxyConfig } from "./config";
import { serveStatic } from "./static_files";
import { DetailDecoder } from "./status_json";
import { Transcoder, sendJson } from "./transcoder";
import { connectUpstreams, loadPackages } from "./upstreams";

// logfmt on stderr, like the services.
function log(level: "info" | "warning", event: string, fields: Record<string, string | number> = {}): void {
  const pairs = Object.entries(fields).map(([k, v]) => `${k}=${/[\s"=]/.test(String(v)) ? JSON.stringify(String(v)) : v}`);
  process.stderr.write(`ts=${new Date().toISOString()} level=${level} svc=semnav-dashboard event=${event} ${pairs.join(" ")}\n`);
}

function start(config: ProxyConfig): http.Server {
  const packages = loadPackages(config.protoDir);
  const transcoder = new Transcoder(connectUpstreams(config, packages), new DetailDecoder(config.protoDir), config);
  const server = http.createServer((request, response) => {
    const url = new URL(request.url ?? "/", "http://dashboard");
    if (config.verbose && url.pathname.startsWith("/api/")) {
      const started = Date.now();
      response.on("close", () => log("info", "request", { method: request.method ?? "", path: url.pathname,
                                                          status: response.statusCode, ms: Date.now() - started }));
    }
    if (url.pathname === "/api/config") {
      sendJson(response, 200, { robot_id: config.robotId, services: transcoder.describe() });
      return;
    }
    if (url.pathname.startsWith("/api/")) {
      transcoder.handle(request, response, url).then((handled) => {
        if (!handled) sendJson(response, 404, { code: "NOT_FOUND", message: `no method ${url.pathname}`, details: [] });
      }, (error: Error) => {
        log("warning", "internal_error", { path: url.pathname, message: error.message });
        sendJson(response, 500, { code: "INTERNAL", message: error.message, details: [] });
      });
      return;
    }
    serveStatic(config.staticDir, url.pathname, response).catch(() => response.destroy());
  });
  const [host, port] = splitHostPort(config.listen);
  server.listen(port, host, () => {
    const address = server.address();
    const bound = typeof address === "object" && address !== null ? `${address.address}:${address.port}` : config.listen;
    if (config.verbose) log("info", "serving", { listen: bound, gateway: config.gateway, mapping: config.mapping, planning: config.planning,
                     tls: config.tls.caFile !== undefined ? "true" : "false" });
    // One machine-readable line on stdout for scripts that pass port 0.
    process.stdout.write(`${JSON.stringify({ listen: bound })}\n`);
  });
  return server;
}

function splitHostPort(listen: string): [string, number] {
  const colon = listen.lastIndexOf(":");
  const port = Number(listen.slice(colon + 1));
  if (colon < 0 || !Number.isInteger(port) || port < 0 || port > 65535) throw new Error(`--listen: expected HOST:PORT, got '${listen}'`);
  return [listen.slice(0, colon).replace(/^\[|\]$/g, ""), port];
}

function main(): void {
  let config: ProxyConfig | undefined;
  try {
    config = parseConfig(process.argv.slice(2), process.env, path.dirname(process.argv[1] ?? "."));
  } catch (error) {
    process.stderr.write(`semnav-dashboard: ${(error as Error).message}\n${usage()}`);
    process.exit(2);
  }
  if (config === undefined) {
    process.stdout.write(usage());
    return;
  }
  const server = start(config);
  for (const signal of ["SIGINT", "SIGTERM"] as const) {
    process.on(signal, () => {
      server.close();
      server.closeAllConnections();
      process.exit(0);
    });
  }
}

main();
