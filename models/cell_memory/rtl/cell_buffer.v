// The grid board's cell buffer (the C++ CellBuffer,
// models/cell_memory/cell_buffer.h; docs/grid_board.md, "The cell sweep").
//
// Two halves, each M copies of a two-port block RAM of C
// entries, an entry a box: {first cells z, y, x (a byte each), its index,
// its six coordinates}. The lanes read one half (port 0 the row, ports
// 1..2M-1 the columns: port 2p + s is copy p's side s), the loader writes the
// other through side A of every copy. The C++ model counts the six
// coordinates' primitives only; the index and first cells ride in the same
// word here, so Yosys counts what a box entry really takes.
module cell_buffer #(
    parameter M = 2,
    parameter EW = 232,     // entry bits: 24 + index + six coordinates
    parameter CAW = 9       // 2^CAW entries a half
) (
    input  wire              clk,
    input  wire              enable,       // a slot: the read ports advance
    input  wire              read_half,    // the half the lanes read
    input  wire [2*M*CAW-1:0] read_addr,   // port k at k*CAW
    output wire [2*M*EW-1:0] read_data,    // port k's entry, a slot after its address
    input  wire              write,
    input  wire              write_half,
    input  wire [CAW-1:0]    write_addr,
    input  wire [EW-1:0]     write_data
);
    reg half_q;
    always @(posedge clk) if (enable) half_q <= read_half;
    genvar h, p;
    generate
        for (p = 0; p < M; p = p + 1) begin : g_copy
            wire [EW-1:0] qa [0:1];
            wire [EW-1:0] qb [0:1];
            for (h = 0; h < 2; h = h + 1) begin : g_half
                wire loading = write && write_half == h;
                cell_copy #(.EW(EW), .CAW(CAW)) copy (
                    .clk(clk), .en_a(enable | loading), .we_a(loading),
                    .addr_a(loading ? write_addr : read_addr[2*p*CAW +: CAW]), .d_a(write_data), .q_a(qa[h]),
                    .en_b(enable), .addr_b(read_addr[(2*p+1)*CAW +: CAW]), .q_b(qb[h]));
            end
            assign read_data[2*p*EW +: EW] = half_q ? qa[1] : qa[0];
            assign read_data[(2*p+1)*EW +: EW] = half_q ? qb[1] : qb[0];
        end
    endgenerate
endmodule

// One copy of one half: side A reads or takes the loader's writes, side B reads.
module cell_copy #(
    parameter EW = 232,
    parameter CAW = 9
) (
    input  wire           clk,
    input  wire           en_a,
    input  wire           we_a,
    input  wire [CAW-1:0] addr_a,
    input  wire [EW-1:0]  d_a,
    output reg  [EW-1:0]  q_a,
    input  wire           en_b,
    input  wire [CAW-1:0] addr_b,
    output reg  [EW-1:0]  q_b
);
    (* ram_style = "block" *) reg [EW-1:0] entries [0:(1<<CAW)-1];
    always @(posedge clk) if (en_a) begin
        if (we_a) entries[addr_a] <= d_a;
        q_a <= entries[addr_a];
    end
    always @(posedge clk) if (en_b) q_b <= entries[addr_b];
endmodule

