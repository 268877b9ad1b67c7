// HTTP/JSON + server-sent events <-> gRPC, for every unary and server-streaming method of the
// upstream services as defined by the loaded protos:
//   POST /api/<service>/<Method>  body = request JSON
//     unary           -> 200 + response JSON, or the mapped HTTP status + ErrorBody
//     server stream   -> text/event-stream: "message" events (one per response), then one "end"
//                        event ({"code":"OK"}) or one "error" event (ErrorBody)
//   GET  /api/<service>/<Method>?request=<JSON>  the same, for EventSource and links
import type { IncomingMessage, ServerResponse } from "node:http";
import * as grpc from "@grpc/grpc-js";
import type { ProxyConfig } from "./config";
import { callSettings, grpcCallOptions } from "./call_options";
import { type DetailDecoder, httpStatus } from "./status_json";
import { SERVICES, type ServiceName, type Upstream } from "./upstreams";

const MAX_BODY_BYTES = 4 << 20;
const HEARTBEAT_MS = 15000;

export class Transcoder {
  constructor(private readonly upstreams: Record<ServiceName, Upstream>,
              private readonly decoder: DetailDecoder,
              private readonly config: ProxyConfig) {}

  // The methods the proxy serves, for /api/describe.
  describe(): object {
    const result: Record<string, object> = {};
    for (const name of Object.keys(this.upstreams) as ServiceName[]) {
      const methods = Object.entries(this.upstreams[name].methods)
        .filter(([, m]) => !m.requestStream)
        .map(([method, m]) => ({ method, streaming: m.responseStream, path: m.path }));
      result[name] = { service: SERVICES[name].service, methods };
    }
    return result;
  }

  // Returns false when the path is not /api/<service>/<Method> of a known method.
  async handle(request: IncomingMessage, response: ServerResponse, url: URL): Promise<boolean> {
    const match = /^\/api\/([a-z]+)\/([A-Za-z]+)$/.exec(url.pathname);
    if (match === null || !(match[1] in this.upstreams)) return false;
    const upstream = this.upstreams[match[1] as ServiceName];
    const method = Object.hasOwn(upstream.methods, match[2]) ? upstream.methods[match[2]] : undefined;
    if (method === undefined || method.requestStream) return false;
    if (request.method !== "POST" && request.method !== "GET") {
      sendJson(response, 405, { code: "INVALID_ARGUMENT", message: "use POST or GET", details: [] });
      return true;
    }
    let body: object;
    let settings;
    try {
      body = request.method === "POST" ? await readJson(request) : JSON.parse(url.searchParams.get("request") ?? "{}");
      settings = callSettings(request, url, method.responseStream ? undefined : this.config.deadlineMs,
                              this.config.upstreamToken);
    } catch (error) {
      sendJson(response, 400, { code: "INVALID_ARGUMENT", message: (error as Error).message, details: [] });
      return true;
    }
    const options = grpcCallOptions(settings);
    if (!method.responseStream) {
      upstream.client.makeUnaryRequest(method.path, method.requestSerialize, method.responseDeserialize, body,
        settings.metadata, options, (error, reply) => {
          if (error) sendJson(response, httpStatus(error.code), this.decoder.toBody(error));
          else sendJson(response, 200, reply ?? {});
        });
      return true;
    }
    this.stream(upstream, method, body, settings.metadata, options, response);
    return true;
  }

  private stream(upstream: Upstream, method: Upstream["methods"][string], body: object, metadata: grpc.Metadata,
                 options: grpc.CallOptions, response: ServerResponse): void {
    let call: grpc.ClientReadableStream<object>;
    try {
      call = upstream.client.makeServerStreamRequest(method.path, method.requestSerialize, method.responseDeserialize,
                                                     body, metadata, options);
    } catch (error) {  // the request JSON does not fit the message
      sendJson(response, 400, { code: "INVALID_ARGUMENT", message: (error as Error).message, details: [] });
      return;
    }
    response.writeHead(200, {
      "content-type": "text/event-stream; charset=utf-8",
      "cache-control": "no-store",
      "x-accel-buffering": "no",
    });
    response.flushHeaders();
    const event = (name: string, data: object) => response.write(`event: ${name}\ndata: ${JSON.stringify(data)}\n\n`);
    const heartbeat = setInterval(() => response.write(": keep-alive\n\n"), HEARTBEAT_MS);
    let finished = false;
    const finish = () => {
      finished = true;
      clearInterval(heartbeat);
      response.end();
    };
    call.on("data", (message: object) => event("message", message));
    call.on("error", (error: grpc.ServiceError) => {
      if (finished) return;
      event("error", this.decoder.toBody(error));
      finish();
    });
    call.on("end", () => {
      if (finished) return;
      event("end", { code: "OK" });
      finish();
    });
    // The browser went away: cancel the upstream stream (no "error" event reaches anyone).
    response.on("close", () => {
      if (finished) return;
      finished = true;
      clearInterval(heartbeat);
      call.cancel();
    });
  }
}

export function sendJson(response: ServerResponse, status: number, body: object): void {
  if (response.headersSent) return;
  const text = JSON.stringify(body);
  response.writeHead(status, { "content-type": "application/json; charset=utf-8", "cache-control": "no-store" });
  response.end(text);
}

async function readJson(request: IncomingMessage): Promise<object> {
  const chunks: Buffer[] = [];
  let size = 0;
  for await (const chunk of request) {
    size += (chunk as Buffer).length;
    if (size > MAX_BODY_BYTES) throw new Error(`request body: larger than ${MAX_BODY_BYTES} bytes`);
    chunks.push(chunk as Buffer);
  }
  const text = Buffer.concat(chunks).toString("utf8");
  if (text.trim() === "") return {};
  const value: unknown = JSON.parse(text);
  if (typeof value !== "object" || value === null || Array.isArray(value)) throw new Error("request body: expected a JSON object");
  return value;
}
