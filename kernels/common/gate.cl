/* gate.cl: the gate's dummies (gate[i] != 0) translate by disp and move at v (the host integrates
 * the lift exactly: solvers/gate/gate.c) */
__kernel void gate_move(const uint n, __global const uint *gate, const realv disp, const realv v,
                        __global realv *pos, __global realv *wall_vel)
{
  const uint i = get_global_id(0);
  if (i >= n || gate[i] == 0u) return;
  pos[i] += disp;
  wall_vel[i] = v;
}
