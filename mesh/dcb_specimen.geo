// A DCB specimen for fiberbridge's FEM: both arms as structured quadrilaterals, optionally with
// linearly tapered arms and with end blocks at the loaded end (read through FEM/Mesh file;
// source/fem/specimen_mesh.h says what the engine expects of a mesh, mesh/README.md how to add one).
//
// The scene gives (mm, from Specimen and FEM): L the length, a0 the initial crack, h the arm
// thickness at the notch tip x = a0, dx the crack-plane element length, layers (Minimum layers
// per arm) and grading. The node layout is the generated mesh's (source/fem/dcb_common.cc,
// dcb_mesh_lines): crack-plane nodes every dx with one at a0, layers from the crack plane with a
// first layer min(dx, h / layers), graded by `grading` and capped at h / layers. With taper = 0
// and no block this file reproduces the generated rectangle node for node.
//
// Own numbers (FEM/Mesh file parameters, "name: value, ..."):
//   taper         slope dh/dx of each arm's outer face (0: plain arms). The arm is h + taper (x -
//                 a0) thick at x; the layers keep their fractions of the local thickness.
//   block_length  [mm] end blocks from the load line x = 0 to block_length (rounded to a whole
//                 number of crack-plane elements), bonded on each arm's outer face; 0: none.
//   block_height  [mm] their height above the arm's face. The blocks are of the arm's material
//                 (the FEM has one material per arm).
Geometry.AutoCoherence = 0; // the two arms' crack-plane points coincide and must stay apart
If (!Exists(taper)) taper = 0; EndIf
If (!Exists(block_length)) block_length = 0; EndIf
If (!Exists(block_height)) block_height = 0; EndIf
If (h + taper * (0 - a0) <= 0 || h + taper * (L - a0) <= 0)
  Error("dcb_specimen.geo: taper %g makes an arm of zero or negative thickness", taper);
  Abort;
EndIf
If (block_length < 0 || block_height < 0 || (block_length > 0) != (block_height > 0))
  Error("dcb_specimen.geo: block_length and block_height must both be positive, or both 0");
  Abort;
EndIf

// x stations: every dx from the load line, a mesh line at a0, the last element up to 1.5 dx.
n_a0 = Round(a0 / dx);
n_x = Max(n_a0 + 1, Floor(L / dx + 1e-9));
xs[] = {};
For i In {0:n_x}
  xs[i] = Min(L, i * dx);
EndFor
If (L - xs[n_x] > 0.5 * dx)
  xs[n_x + 1] = L;
Else
  xs[n_x] = L;
EndIf
nc = #xs[] - 1; // columns

// Layer heights at the notch tip as fractions of h.
cap = h / layers;
size = Min(dx, cap);
ys[] = {0};
For j In {1:Ceil(h / size) + 2}
  If (ys[#ys[] - 1] + size < h - 1e-12 * h)
    ys[#ys[]] = ys[#ys[] - 1] + size;
    size = Min(size * grading, cap);
  EndIf
EndFor
If (h - ys[#ys[] - 1] < 0.5 * size && #ys[] > 1)
  ys[#ys[] - 1] = h;
Else
  ys[#ys[]] = h;
EndIf
ny = #ys[] - 1; // layers through the arm

// End blocks: columns 0 .. nbc - 1, nbl uniform layers above the arm's face.
nbc = 0;
nbl = 0;
If (block_length > 0)
  nbc = Max(1, Round(block_length / dx));
  If (nbc >= n_a0)
    Error("dcb_specimen.geo: block_length %g mm reaches the notch tip a0 = %g mm", block_length, a0);
    Abort;
  EndIf
  nbl = Max(1, Ceil(block_height / Max(cap, dx) - 1e-9)); // about square elements
EndIf
nr = ny + nbl + 1;         // rows of points in a column
np = (nc + 1) * nr;        // point ids per arm

upper[] = {};
lower[] = {};
For s In {0:1}
  sign = 1 - 2 * s;        // upper arm y > 0, lower arm y < 0
  For i In {0:nc}
    x = xs[i];
    t = h + taper * (x - a0);
    top = ny;
    If (i <= nbc && nbc > 0)
      top = ny + nbl;
    EndIf
    For j In {0:top}
      If (j <= ny)
        y = ys[j] / h * t;
      Else
        y = t + (j - ny) * block_height / nbl;
      EndIf
      Point(1 + s * np + i * nr + j) = {x, sign * y, 0};
    EndFor
  EndFor
  // Lines: horizontal (i, j) -> (i + 1, j) with id 2 k + 1, vertical (i, j) -> (i, j + 1) with
  // id 2 k + 2, k = s np + i nr + j.
  For i In {0:nc}
    top = ny;
    If (i <= nbc && nbc > 0)
      top = ny + nbl;
    EndIf
    For j In {0:top}
      k = s * np + i * nr + j;
      If (i < nc && (j <= ny || i < nbc))
        Line(2 * k + 1) = {1 + k, 1 + k + nr};
      EndIf
      If (j < top)
        Line(2 * k + 2) = {1 + k, 2 + k};
      EndIf
    EndFor
  EndFor
  // Quadrilaterals, counter-clockwise on both arms.
  For i In {0:nc - 1}
    top = ny;
    If (i < nbc)
      top = ny + nbl;
    EndIf
    For j In {0:top - 1}
      k = s * np + i * nr + j;
      If (s == 0)
        Curve Loop(1 + k) = {2 * k + 1, 2 * (k + nr) + 2, -(2 * (k + 1) + 1), -(2 * k + 2)};
      Else
        Curve Loop(1 + k) = {2 * k + 2, 2 * (k + 1) + 1, -(2 * (k + nr) + 2), -(2 * k + 1)};
      EndIf
      Plane Surface(1 + k) = {1 + k};
      If (s == 0)
        upper[] += {1 + k};
      Else
        lower[] += {1 + k};
      EndIf
    EndFor
  EndFor
EndFor

Transfinite Curve{:} = 2; // one element per line: the nodes are the points above
Transfinite Surface{:};
Recombine Surface{:};
Physical Surface(1) = {upper[]}; // the upper arm (material id 0 in the engine)
Physical Surface(2) = {lower[]}; // the lower arm (material id 1)
