// The live grid: a WatchGridMap snapshot patched by its sub-window deltas, and each layer's
// cells drawn into an image (one pixel per cell, row 0 at the bottom).
import type { semnav } from "../generated/protos";

type GridMap = semnav.common.v1.GridMap;
type LayerKind = semnav.common.v1.GridLayerKind;

const UNKNOWN = 255;
// Value of a cell nobody has seen, per layer (255 unless the layer says otherwise).
const UNOBSERVED: Partial<Record<LayerKind, number>> = { GRID_LAYER_KIND_EXPLORED: 0, GRID_LAYER_KIND_SEMANTIC: 0 };

export class LiveGrid {
  grid: GridMap | null = null;
  private layers = new Map<LayerKind, Uint8Array>();

  get revision(): string {
    return this.grid?.revision ?? "0";
  }

  apply(update: semnav.mapping.v1.WatchGridMapResponse): void {
    const part = update.grid;
    if (part === null) return;
    if (update.snapshot || this.grid === null) {
      this.grid = part;
      this.layers = new Map(part.layers.map((l) => [l.kind, decodeBase64(l.data)]));
      return;
    }
    // The delta covers every changed cell; the whole-map watch grows with the map.
    const resolution = this.grid.resolution;
    const cell = (metres: number, origin: number) => Math.round((metres - origin) / resolution);
    const ox = this.grid.origin?.x ?? 0, oy = this.grid.origin?.y ?? 0;
    let column0 = cell(part.origin?.x ?? 0, ox), row0 = cell(part.origin?.y ?? 0, oy);
    if (column0 < 0 || row0 < 0 || column0 + part.width > this.grid.width || row0 + part.height > this.grid.height) {
      const left = Math.min(0, column0), bottom = Math.min(0, row0);
      const width = Math.max(this.grid.width, column0 + part.width) - left;
      const height = Math.max(this.grid.height, row0 + part.height) - bottom;
      this.resize(-left, -bottom, width, height);
      column0 -= left;
      row0 -= bottom;
    }
    for (const layer of part.layers) {
      const target = this.layers.get(layer.kind);
      if (target === undefined) continue;
      const cells = decodeBase64(layer.data);
      for (let row = 0; row < part.height; ++row) {
        target.set(cells.subarray(row * part.width, (row + 1) * part.width), (row0 + row) * this.grid.width + column0);
      }
    }
    this.grid = { ...this.grid, revision: part.revision };
  }

  // Moves the cells by (shiftColumns, shiftRows) into a width x height grid; new cells unknown.
  private resize(shiftColumns: number, shiftRows: number, width: number, height: number): void {
    const grid = this.grid!;
    for (const [kind, cells] of this.layers) {
      const grown = new Uint8Array(width * height).fill(UNOBSERVED[kind] ?? UNKNOWN);
      for (let row = 0; row < grid.height; ++row) {
        grown.set(cells.subarray(row * grid.width, (row + 1) * grid.width), (row + shiftRows) * width + shiftColumns);
      }
      this.layers.set(kind, grown);
    }
    const origin = { x: (grid.origin?.x ?? 0) - shiftColumns * grid.resolution, y: (grid.origin?.y ?? 0) - shiftRows * grid.resolution, yaw: 0 };
    this.grid = { ...grid, origin, width, height };
  }

  layer(kind: LayerKind): Uint8Array | undefined {
    return this.layers.get(kind);
  }

  // Cells whose hierarchical value is known (not 255).
  knownCells(): number {
    const cells = this.layers.get("GRID_LAYER_KIND_HIERARCHICAL");
    if (cells === undefined) return 0;
    let count = 0;
    for (const value of cells) if (value !== UNKNOWN) ++count;
    return count;
  }

  // RGBA image of one layer, rows flipped so that +y is up.
  render(kind: LayerKind): ImageData | null {
    const grid = this.grid;
    const cells = this.layers.get(kind);
    // A stack whose robot has sent no frame yet has an empty map: nothing to draw (ImageData throws on 0).
    if (grid === null || cells === undefined || grid.width <= 0 || grid.height <= 0) return null;
    const image = new ImageData(grid.width, grid.height);
    const colour = COLOURS[kind];
    for (let row = 0; row < grid.height; ++row) {
      const out = (grid.height - 1 - row) * grid.width;
      for (let column = 0; column < grid.width; ++column) {
        const rgba = colour(cells[row * grid.width + column]);
        image.data.set(rgba, (out + column) * 4);
      }
    }
    return image;
  }
}

type Rgba = [number, number, number, number];
const UNKNOWN_RGBA: Rgba = [0, 0, 0, 0];  // the canvas background shows through
const FREE_RGBA: Rgba = [245, 242, 234, 255];

function mix(a: Rgba, b: Rgba, t: number): Rgba {
  return [0, 1, 2, 3].map((i) => Math.round(a[i] + (b[i] - a[i]) * t)) as Rgba;
}

function percentRamp(low: Rgba, high: Rgba): (value: number) => Rgba {
  return (value) => (value === UNKNOWN ? UNKNOWN_RGBA : mix(low, high, Math.min(value, 100) / 100));
}

const COLOURS: Record<LayerKind, (value: number) => Rgba> = {
  GRID_LAYER_KIND_UNSPECIFIED: () => UNKNOWN_RGBA,
  // 0 free, 1-99 obstacle height (flyable), 100 structure, 255 unknown.
  GRID_LAYER_KIND_HIERARCHICAL: (v) =>
    v === UNKNOWN ? UNKNOWN_RGBA : v === 0 ? FREE_RGBA : v >= 100 ? [59, 63, 70, 255] : mix([240, 200, 140, 255], [168, 96, 36, 255], v / 99),
  GRID_LAYER_KIND_OCCUPANCY: percentRamp(FREE_RGBA, [40, 44, 52, 255]),
  GRID_LAYER_KIND_OBSTACLE_PROBABILITY: percentRamp(FREE_RGBA, [201, 42, 42, 255]),
  GRID_LAYER_KIND_INFLATED: (v) => (v === UNKNOWN ? UNKNOWN_RGBA : v >= 100 ? [59, 63, 70, 255] : mix(FREE_RGBA, [250, 176, 5, 255], v / 99)),
  GRID_LAYER_KIND_EXPLORED: (v) => (v === 0 ? UNKNOWN_RGBA : [165, 216, 255, 255]),
  GRID_LAYER_KIND_SEMANTIC: (v) => (v === 0 ? FREE_RGBA : labelColour(v)),
};

export function labelColour(index: number): Rgba {
  const hue = (index * 137.508) % 360;
  const c = 0.6, x = c * (1 - Math.abs(((hue / 60) % 2) - 1)), m = 0.25;
  const [r, g, b] = hue < 60 ? [c, x, 0] : hue < 120 ? [x, c, 0] : hue < 180 ? [0, c, x] : hue < 240 ? [0, x, c] : hue < 300 ? [x, 0, c] : [c, 0, x];
  return [Math.round((r + m) * 255), Math.round((g + m) * 255), Math.round((b + m) * 255), 255];
}

function decodeBase64(text: string): Uint8Array {
  const binary = atob(text);
  const bytes = new Uint8Array(binary.length);
  for (let i = 0; i < binary.length; ++i) bytes[i] = binary.charCodeAt(i);
  return bytes;
}
