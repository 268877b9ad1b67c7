// Reads an OctoMap binary tree file (OcTree::writeBinary, ".bt"): a text header, then per inner
// node two bytes with a bit pair per child i (children 0-3, then 4-7): none set = unknown, bit 2i
// alone = free leaf, bit 2i+1 alone = occupied leaf, both = inner node (recursed into, depth
// first). Child i is on the upper side of axis a when bit a of i is set.
export interface OctomapBt {
  id: string;
  resolution: number;
  // Centres (x, y, z, metres) of the occupied and free leaves; pruned leaves count once.
  occupied: number[][];
  free: number[][];
}

const treeDepth = 16;

export function parseOctomapBt(payload: Buffer): OctomapBt {
  const header: Record<string, string> = {};
  let at = 0;
  for (;;) {
    const end = payload.indexOf(0x0a, at);
    if (end < 0) throw new Error('.bt header has no "data" line');
    const line = payload.toString('latin1', at, end);
    at = end + 1;
    if (line === 'data') break;
    if (line.startsWith('#')) continue;
    const [key, value] = line.split(' ');
    header[key] = value;
  }
  const resolution = Number(header.res);
  const result: OctomapBt = { id: header.id, resolution, occupied: [], free: [] };
  let nodes = 0;
  // Node `depth` centred at `centre` has half size resolution * 2^(treeDepth - depth - 1).
  const readNode = (depth: number, centre: number[]) => {
    ++nodes;
    if (at + 2 > payload.length) throw new Error(`.bt data truncated at byte ${at}`);
    const bits = payload[at] | (payload[at + 1] << 8);
    at += 2;
    const quarter = resolution * 2 ** (treeDepth - depth - 2);
    for (let child = 0; child < 8; ++child) {
      const pair = (bits >> (2 * child)) & 3;
      if (pair === 0) continue;
      const childCentre = centre.map((c, axis) => c + (((child >> axis) & 1) ? quarter : -quarter));
      if (pair === 3) readNode(depth + 1, childCentre);
      else {
        ++nodes;
        (pair === 2 ? result.occupied : result.free).push(childCentre);
      }
    }
  };
  if (Number(header.size) > 0) readNode(0, [0, 0, 0]);  // an empty tree has no data
  if (at !== payload.length) throw new Error(`.bt has ${payload.length - at} bytes after the tree`);
  if (Number(header.size) !== nodes) throw new Error(`.bt header says ${header.size} nodes, the tree has ${nodes}`);
  return result;
}
