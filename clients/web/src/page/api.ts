// The proxy's HTTP/JSON + SSE API (see docs/dashboard.md): unary calls, and server streams that
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

export interface Subscription<Message> {
  service: Service;
  method: string;
  request: () => object;                 // built again on every (re)connect, to resume
  onMessage: (message: Message) => void;
  onStatus?: (connected: boolean) => void;
  onEnd?: () => void;                    // the stream ended OK: it is dropped
}

// Every server stream of the page over one /api/streams connection (a browser allows only six
// HTTP/1.1 connections per host, and unary calls need some). Subscribing or unsubscribing
// reopens the connection with every stream's resume request; so does an error, after a pause
// that grows while errors repeat.
export class StreamHub {
  private readonly subscriptions = new Map<string, Subscription<never>>();
  private abort: AbortController | null = null;
  private retryMs = 500;
  private reconnectTimer = 0;

  subscribe<Message>(name: string, subscription: Subscription<Message>): void {
    this.subscriptions.set(name, subscription as Subscription<never>);
    this.reconnect(0);
  }

  unsubscribe(name: string): void {
    if (this.subscriptions.delete(name)) this.reconnect(0);
  }

  private reconnect(delayMs: number): void {
    clearTimeout(this.reconnectTimer);
    this.reconnectTimer = window.setTimeout(() => void this.connect(), delayMs);
  }

  private async connect(): Promise<void> {
    this.abort?.abort();
    if (this.subscriptions.size === 0) return;
    const abort = (this.abort = new AbortController());
    const body: Record<string, object> = {};
    for (const [name, s] of this.subscriptions) body[name] = { service: s.service, method: s.method, request: s.request() };
    try {
      const reply = await fetch("/api/streams", { method: "POST", headers: headers(), body: JSON.stringify(body), signal: abort.signal });
      if (!reply.ok || reply.body === null) throw new CallError(await reply.json() as ApiError);
      for (const s of this.subscriptions.values()) s.onStatus?.(true);
      await readEvents(reply.body, (event, data) => {
        const { stream, message } = JSON.parse(data) as { stream: string; message: never };
        const subscription = this.subscriptions.get(stream);
        if (subscription === undefined) return;
        if (event === "message") {
          this.retryMs = 500;
          subscription.onMessage(message);
        } else if (event === "end") {
          this.subscriptions.delete(stream);
          subscription.onEnd?.();
        } else if (event === "error") {
          subscription.onStatus?.(false);
          this.reconnect(this.retryMs);
          this.retryMs = Math.min(this.retryMs * 2, 5000);
        }
      });
    } catch {
      if (abort.signal.aborted) return;
    }
    if (abort.signal.aborted) return;
    for (const s of this.subscriptions.values()) s.onStatus?.(false);
    this.reconnect(this.retryMs);
    this.retryMs = Math.min(this.retryMs * 2, 5000);
  }
}

// Parses text/event-stream until the connection closes.
async function readEvents(body: ReadableStream<Uint8Array>, onEvent: (event: string, data: string) => void): Promise<void> {
  const reader = body.getReader();
  const decoder = new TextDecoder();
  let buffer = "";
  for (;;) {
    const { value, done } = await reader.read();
    if (done) return;
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
      if (data.length > 0) onEvent(event, data.join("\n"));
    }
  }
}

export function requestId(): string {
  return crypto.randomUUID();
}
