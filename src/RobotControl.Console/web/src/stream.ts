// One WebSocket to /api/stream: subscribe to signals, receive the rows recorded since the last frame.
export interface Frame { t: number[]; v: number[][]; seq: number; serverMs: number }

export class SignalStream {
  private socket: WebSocket | null = null;
  private names: string[] = [];
  private closed = false;

  constructor(private readonly onFrame: (names: string[], frame: Frame) => void, private readonly rateHz = 60) {
    this.open();
  }

  subscribe(names: string[]): void {
    this.names = [...names];
    if (this.socket?.readyState === WebSocket.OPEN) {
      this.socket.send(JSON.stringify({ subscribe: this.names, rateHz: this.rateHz }));
    }
  }

  close(): void {
    this.closed = true;
    this.socket?.close();
  }

  private open(): void {
    const url = `${location.protocol === 'https:' ? 'wss' : 'ws'}://${location.host}/api/stream`;
    const socket = new WebSocket(url);
    this.socket = socket;
    socket.onopen = () => socket.send(JSON.stringify({ subscribe: this.names, rateHz: this.rateHz }));
    socket.onmessage = (e) => {
      const message = JSON.parse(e.data as string);
      if (Array.isArray(message.t)) {
        this.onFrame(this.names, message as Frame);
      }
    };
    socket.onclose = () => {
      if (!this.closed) {
        setTimeout(() => this.open(), 1000);
      }
    };
  }
}
