// A simple dual-port memory (one write port, one synchronous read port):
// the pair buffer, written by the collector, read by the host.
module board_sdp_ram #(
    parameter W = 32,
    parameter DEPTH = 512,
    parameter AW = 9
) (
    input  wire          clk,
    input  wire          we,
    input  wire [AW-1:0] waddr,
    input  wire [W-1:0]  d,
    input  wire          re,
    input  wire [AW-1:0] raddr,
    output reg  [W-1:0]  q
);
    (* ram_style = "block" *) reg [W-1:0] cells [0:DEPTH-1];
    always @(posedge clk) if (we) cells[waddr] <= d;
    always @(posedge clk) if (re) q <= cells[raddr];
endmodule

// One copy of the six coordinate memories (min x, y, z, max x, y, z) as one
// block RAM word of six coordinates (a box a word, coordinate c at c*W):
// Yosys cuts it into block RAM primitives side by side, each coordinate
// written on its own enable. Side A reads box q_a or takes writes (we, one
// bit a coordinate, all at addr_a), side B reads box q_b. (One word a box,
// not six arrays, also keeps Icarus fast: a box changes as one vector.)
module coordinate_copy #(
    parameter W = 32,
    parameter AW = 9
) (
    input  wire            clk,
    input  wire            en_a,
    input  wire [5:0]      we,
    input  wire [AW-1:0]   addr_a,
    input  wire [6*32-1:0] d,     // host words: each memory keeps the low W bits
    output reg  [6*W-1:0]  q_a,
    input  wire            en_b,
    input  wire [AW-1:0]   addr_b,
    output reg  [6*W-1:0]  q_b
);
    (* ram_style = "block" *) reg [6*W-1:0] cells [0:(1<<AW)-1];
    integer c;
    always @(posedge clk) begin
        if (en_a) begin
            for (c = 0; c < 6; c = c + 1) if (we[c]) cells[addr_a][c*W +: W] <= d[c*32 +: W];
            q_a <= cells[addr_a];
        end
    end
    always @(posedge clk) if (en_b) q_b <= cells[addr_b];
endmodule
