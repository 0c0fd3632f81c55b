// The part of drawflow 0.0.60's API the graph editor uses (the package ships no types).
declare module 'drawflow' {
  export interface DrawflowConnection { node: string; output?: string; input?: string }
  export interface DrawflowNode {
    id: number; name: string; pos_x: number; pos_y: number;
    inputs: Record<string, { connections: DrawflowConnection[] }>;
    outputs: Record<string, { connections: DrawflowConnection[] }>;
  }
  export interface ConnectionEvent { output_id: string; input_id: string; output_class: string; input_class: string }
  export default class Drawflow {
    constructor(container: HTMLElement);
    reroute: boolean;
    zoom: number;
    zoom_min: number;
    zoom_max: number;
    canvas_x: number;
    canvas_y: number;
    precanvas: HTMLElement;
    start(): void;
    clear(): void;
    addNode(name: string, inputs: number, outputs: number, x: number, y: number, className: string, data: object, html: string, typenode?: boolean): number;
    addConnection(outputId: number, inputId: number, outputClass: string, inputClass: string): void;
    removeSingleConnection(outputId: number, inputId: number, outputClass: string, inputClass: string): boolean;
    removeNodeId(id: string): void;
    getNodeFromId(id: number | string): DrawflowNode;
    updateConnectionNodes(id: string): void;
    zoom_refresh(): void;
    on(event: 'connectionCreated' | 'connectionRemoved' | 'connectionSelected', handler: (e: ConnectionEvent) => void): void;
    on(event: 'nodeMoved' | 'nodeRemoved' | 'nodeSelected', handler: (id: string) => void): void;
    on(event: 'nodeUnselected' | 'connectionUnselected', handler: () => void): void;
    on(event: 'zoom', handler: (zoom: number) => void): void;
  }
}
