mcsf_begin=1;

      dim=3;
    dimii=3;
 vertices=5;
simplices=2;

vert=[
% comment
0 0 0 0 0
1 0 1 0 0
2 0 0 1 0
3 0 0 0 1
4 0 1 1 1
];

simp=[
0 0 1 1 1 1 0 0 1 2 3
1 0 2 0 2 3 1 1 2 3 4
];

mcsf_end=1;
