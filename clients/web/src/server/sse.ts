// A text/event-stream response: named events with JSON data, comment heartbeats so idle
// proxies keep the connection, and a close hook for when the browser goes away.
import type { ServerResponse } from "node:http";

const HEARTBEAT_MS = 15000;

export class EventStream {
  private readonly heartbeat: NodeJS.Timeout;
  private closed = false;

  constructor(private readonly response: ServerResponse, onClientGone: () => void) {
    response.writeHead(200, {
      "content-type": "text/event-stream; charset=utf-8",
      "cache-control": "no-store",
      "x-accel-buffering": "no",
    });
    response.flushHeaders();
    this.heartbeat = setInterval(() => response.write(": keep-alive\n\n"), HEARTBEAT_MS);
    response.on("close", () => {
      if (this.closed) return;
      this.closed = true;
      clearInterval(this.heartbeat);
      onClientGone();
    });
  }

  send(event: string, data: object): void {
    if (!this.closed) this.response.write(`event: ${event}\ndata: ${JSON.stringify(data)}\n\n`);
  }

  end(): void {
    if (this.closed) return;
    this.closed = true;
    clearInterval(this.heartbeat);
    this.response.end();
  }
}
