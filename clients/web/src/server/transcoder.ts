// HTTP/JSON + server-sent events <-> gRPC, for every unary and server-streaming method of the
// upstream services as defined by the loaded protos (docs/dashboard.md has the full mapping):
//   POST /api/<service>/<Method>  body = request JSON
//     unary           -> 200 + response JSON, or the mapped HTTP status + ErrorBody
//     server stream   -> text/event-stream: "message" events (one per response), then one "end"
//                        event ({"code":"OK"}) or one "error" event (ErrorBody)
//   GET  /api/<service>/<Method>?request=<JSON>  the same, for EventSource and links
//   POST /api/streams  body = {"<name>": {"service", "method", "request"}, ...}: several server
//     streams over one connection (browsers allow only six HTTP/1.1 connections per host);
//     events carry {"stream": name, ...} and the connection ends when every stream has.
import type { IncomingMessage, ServerResponse } from "node:http";
import * as grpc from "@grpc/grpc-js";
import type { ProxyConfig } from "./config";
import { type CallSettings, callSettings, grpcCallOptions } from "./call_options";
import { EventStream } from "./sse";
import { type DetailDecoder, type ErrorBody, httpStatus } from "./status_json";
import { SERVICES, type ServiceName, type Upstream } from "./upstreams";

const MAX_BODY_BYTES = 4 << 20;

type Method = Upstream["methods"][string];

class BadRequest extends Error {}

export class Transcoder {
  constructor(private readonly upstreams: Record<ServiceName, Upstream>,
              private readonly decoder: DetailDecoder,
              private readonly config: ProxyConfig) {}

  // The methods the proxy serves, for /api/config.
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

  // Returns false when the path is neither /api/streams nor /api/<service>/<Method> of a known method.
  async handle(request: IncomingMessage, response: ServerResponse, url: URL): Promise<boolean> {
    const match = /^\/api\/([a-z]+)\/([A-Za-z]+)$/.exec(url.pathname);
    const method = match === null ? undefined : this.method(match[1], match[2]);
    if (url.pathname !== "/api/streams" && method === undefined) return false;
    try {
      if (request.method !== "POST" && request.method !== "GET") throw new BadRequest("use POST or GET");
      const body = request.method === "POST" ? await readJson(request) : parseObject(url.searchParams.get("request") ?? "{}");
      if (method === undefined) {
        this.multiplex(body, callSettings(request, url, undefined, this.config.upstreamToken), response);
        return true;
      }
      const settings = callSettings(request, url, method.responseStream ? undefined : this.config.deadlineMs,
                                    this.config.upstreamToken);
      const service = this.upstreams[match![1] as ServiceName];
      if (method.responseStream) this.single(service, method, body, settings, response);
      else this.unary(service, method, body, settings, response);
    } catch (error) {
      const message = (error as Error).message;
      sendJson(response, 400, { code: "INVALID_ARGUMENT", message, details: [] });
    }
    return true;
  }

  private method(service: string, name: string): Method | undefined {
    if (!Object.hasOwn(this.upstreams, service)) return undefined;
    const methods = this.upstreams[service as ServiceName].methods;
    const method = Object.hasOwn(methods, name) ? methods[name] : undefined;
    return method === undefined || method.requestStream ? undefined : method;
  }

  private unary(upstream: Upstream, method: Method, body: object, settings: CallSettings, response: ServerResponse): void {
    upstream.client.makeUnaryRequest(method.path, method.requestSerialize, method.responseDeserialize, body,
      settings.metadata, grpcCallOptions(settings), (error, reply) => {
        if (error) sendJson(response, httpStatus(error.code), this.decoder.toBody(error));
        else sendJson(response, 200, reply ?? {});
      });
  }

  // Throws BadRequest when the request JSON does not fit the message.
  private open(upstream: Upstream, method: Method, body: object, settings: CallSettings): grpc.ClientReadableStream<object> {
    try {
      return upstream.client.makeServerStreamRequest(method.path, method.requestSerialize, method.responseDeserialize,
                                                     body, settings.metadata, grpcCallOptions(settings));
    } catch (error) {
      throw new BadRequest((error as Error).message);
    }
  }

  private single(upstream: Upstream, method: Method, body: object, settings: CallSettings, response: ServerResponse): void {
    const call = this.open(upstream, method, body, settings);
    const events = new EventStream(response, () => call.cancel());
    this.forward(call, (message) => events.send("message", message), (error) => {
      events.send(error === null ? "end" : "error", error ?? { code: "OK" });
      events.end();
    });
  }

  private multiplex(body: object, settings: CallSettings, response: ServerResponse): void {
    const specs = Object.entries(body as Record<string, { service?: string; method?: string; request?: object }>)
      .map(([name, spec]) => {
        const method = this.method(spec?.service ?? "", spec?.method ?? "");
        if (method === undefined || !method.responseStream) {
          throw new BadRequest(`${name}: no server-streaming method ${spec?.service}/${spec?.method}`);
        }
        return { name, upstream: this.upstreams[spec.service as ServiceName], method, request: spec.request ?? {} };
      });
    const calls: { name: string; call: grpc.ClientReadableStream<object> }[] = [];
    try {
      for (const spec of specs) calls.push({ name: spec.name, call: this.open(spec.upstream, spec.method, spec.request, settings) });
    } catch (error) {
      calls.forEach(({ call }) => call.cancel());
      throw error;
    }
    const events = new EventStream(response, () => calls.forEach(({ call }) => call.cancel()));
    let open = calls.length;
    if (open === 0) events.end();
    for (const { name, call } of calls) {
      this.forward(call, (message) => events.send("message", { stream: name, message }), (error) => {
        events.send(error === null ? "end" : "error", { stream: name, ...(error ?? { code: "OK" }) });
        if (--open === 0) events.end();
      });
    }
  }

  // Calls onDone once: with null when the stream ended OK, else with the error body.
  private forward(call: grpc.ClientReadableStream<object>, onMessage: (message: object) => void,
                  onDone: (error: ErrorBody | null) => void): void {
    let done = false;
    call.on("data", onMessage);
    call.on("error", (error: grpc.ServiceError) => {
      if (!done) onDone(this.decoder.toBody(error));
      done = true;
    });
    call.on("end", () => {
      if (!done) onDone(null);
      done = true;
    });
  }
}

export function sendJson(response: ServerResponse, status: number, body: object): void {
  if (response.headersSent) return;
  response.writeHead(status, { "content-type": "application/json; charset=utf-8", "cache-control": "no-store" });
  response.end(JSON.stringify(body));
}

function parseObject(text: string): object {
  let value: unknown;
  try {
    value = text.trim() === "" ? {} : JSON.parse(text);
  } catch (error) {
    throw new BadRequest(`request: ${(error as Error).message}`);
  }
  if (typeof value !== "object" || value === null || Array.isArray(value)) throw new BadRequest("request: expected a JSON object");
  return value;
}

async function readJson(request: IncomingMessage): Promise<object> {
  const chunks: Buffer[] = [];
  let size = 0;
  for await (const chunk of request) {
    size += (chunk as Buffer).length;
    if (size > MAX_BODY_BYTES) throw new BadRequest(`request body: larger than ${MAX_BODY_BYTES} bytes`);
    chunks.push(chunk as Buffer);
  }
  return parseObject(Buffer.concat(chunks).toString("utf8"));
}
