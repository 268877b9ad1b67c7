// The proxy's HTTP/JSON + SSE API (see docs/dashboard.md): unary calls and server streams that
// reconnect by themselves, with the operator's bearer token from ?token= (kept for the session).
export type Service = "operator" | "mapping" | "planning";

export interface ApiError {
  code: string;
  message: string;
  details: { "@type": string; [field: string]: unknown }[];
}

export class CallError extends Error {
  constructor(readonly body: ApiError) {
    super(`${body.code}: ${body.message}`);
  }
}

function token(): string | null {
  const fromUrl = new URLSearchParams(location.search).get("token");
  if (fromUrl !== null) sessionStorage.setItem("semnav-token", fromUrl);
  return sessionStorage.getItem("semnav-token");
}

function headers(timeoutMs?: number): HeadersInit {
  const result: Record<string, string> = { "content-type": "application/json" };
  const bearer = token();
  if (bearer !== null) result.authorization = `Bearer ${bearer}`;
  if (timeoutMs !== undefined) result["grpc-timeout"] = `${Math.ceil(timeoutMs)}m`;
  return result;
}

export async function call<Response>(service: Service, method: string, request: object, timeoutMs = 10000): Promise<Response> {
  const reply = await fetch(`/api/${service}/${method}`, { method: "POST", headers: headers(timeoutMs), body: JSON.stringify(request) });
  const body = await reply.json();
  if (!reply.ok) throw new CallError(body as ApiError);
  return body as Response;
}

export interface StreamHandlers<Message> {
  request: () => object;                 // built again on every (re)connect, to resume
  onMessage: (message: Message) => void;
  onStatus?: (connected: boolean, error?: ApiError) => void;
  onEnd?: () => void;                    // the stream ended OK: not reopened
}

// A server stream read with fetch (so the token header goes along), reopened after errors with
// a growing pause; close() stops it.
export function stream<Message>(service: Service, method: string, handlers: StreamHandlers<Message>): { close(): void } {
  const abort = new AbortController();
  let retryMs = 500;
  const run = async () => {
    while (!abort.signal.aborted) {
      let ended = false;
      try {
        const reply = await fetch(`/api/${service}/${method}`, {
          method: "POST", headers: headers(), body: JSON.stringify(handlers.request()), signal: abort.signal,
        });
        if (!reply.ok || reply.body === null) throw new CallError(await reply.json() as ApiError);
        handlers.onStatus?.(true);
        ended = await readEvents(reply.body, (event, data) => {
          if (event === "message") {
            retryMs = 500;
            handlers.onMessage(JSON.parse(data) as Message);
          } else if (event === "error") {
            throw new CallError(JSON.parse(data) as ApiError);
          }
        });
      } catch (error) {
        if (abort.signal.aborted) return;
        handlers.onStatus?.(false, error instanceof CallError ? error.body : { code: "UNAVAILABLE", message: String(error), details: [] });
      }
      if (ended) {
        handlers.onEnd?.();
        return;
      }
      await new Promise((resolve) => setTimeout(resolve, retryMs));
      retryMs = Math.min(retryMs * 2, 5000);
    }
  };
  void run();
  return { close: () => abort.abort() };
}

// Parses text/event-stream; returns true when the "end" event arrived.
async function readEvents(body: ReadableStream<Uint8Array>, onEvent: (event: string, data: string) => void): Promise<boolean> {
  const reader = body.getReader();
  const decoder = new TextDecoder();
  let buffer = "";
  for (;;) {
    const { value, done } = await reader.read();
    if (done) return false;
    buffer += decoder.decode(value, { stream: true });
    let boundary;
    while ((boundary = buffer.indexOf("\n\n")) >= 0) {
      const block = buffer.slice(0, boundary);
      buffer = buffer.slice(boundary + 2);
      let event = "message";
      const data: string[] = [];
      for (const line of block.split("\n")) {
        if (line.startsWith("event: ")) event = line.slice(7);
        else if (line.startsWith("data: ")) data.push(line.slice(6));
      }
      if (event === "end") return true;
      if (data.length > 0) onEvent(event, data.join("\n"));
    }
  }
}

export function requestId(): string {
  return crypto.randomUUID();
}
