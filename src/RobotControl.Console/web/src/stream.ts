// One WebSocket to /api/stream: subscribe to signals, receive the rows recorded since the last frame.
import { noticeInstance, reached, token } from './api';
export interface Frame { t: number[]; v: number[][]; seq: number; id: number; dropped: number; serverMs: number }

export class SignalStream {
  private socket: WebSocket | null = null;
  private names: string[] = [];
  // Each subscription is numbered; the server echoes the number in every frame, so a frame still in flight from
  // an earlier subscription is never read with the new names.
  private id = 0;
  private readonly sent = new Map<number, string[]>();
  private closed = false;

  constructor(private readonly onFrame: (names: string[], frame: Frame) => void, private readonly rateHz = 60) {
    this.open();
  }

  subscribe(names: string[]): void {
    this.names = [...names];
    if (this.socket?.readyState === WebSocket.OPEN) {
      this.send(this.socket);
    }
  }

  private send(socket: WebSocket): void {
    this.id += 1;
    this.sent.clear();
    this.sent.set(this.id, this.names);
    socket.send(JSON.stringify({ subscribe: this.names, rateHz: this.rateHz, id: this.id }));
  }

  close(): void {
    this.closed = true;
    this.socket?.close();
  }

  private open(): void {
    const url = `${location.protocol === 'https:' ? 'wss' : 'ws'}://${location.host}/api/stream?token=${encodeURIComponent(token ?? '')}`;
    const socket = new WebSocket(url);
    this.socket = socket;
    socket.onopen = () => {
      reached(true);
      this.send(socket);
    };
    socket.onmessage = (e) => {
      const message = JSON.parse(e.data as string);
      if (typeof message.instance === 'string') noticeInstance(message.instance); // ahead of the new run's first frame
      const names = Array.isArray(message.t) ? this.sent.get((message as Frame).id) : undefined;
      if (names) {
        this.onFrame(names, message as Frame);
      }
    };
    socket.onclose = () => {
      if (!this.closed) {
        reached(false); // the stream dropped: the status bar says so at once
        setTimeout(() => this.open(), 1000);
      }
    };
  }
}
