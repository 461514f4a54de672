// The pair FIFO: takes a cycle's lane hits as (row, first + k) pairs, all
// or none (the board holds the pipeline while the FIFO lacks room for all
// of a cycle's hits), and hands DRAIN pairs a cycle on to the pair buffer, in
// row-then-column order. LANES banks written round robin keep that order:
// hit k goes to bank (write + number of hits below k) mod LANES, so a cycle
// with h hits writes h different banks at once.
module pair_collector #(
    parameter M = 8,
    parameter AW = 9,
    parameter DEPTH = 512,   // pairs
    parameter DRAIN = 1      // pairs a cycle to the pair buffer
) (
    input  wire                  clk,
    input  wire                  clear,
    input  wire [2*M-2:0]        hits,
    input  wire [AW-1:0]         row,
    input  wire [AW-1:0]         first,
    input  wire                  drain_ready,  // the pair buffer takes pairs
    output wire                  room,         // this cycle's hits fit
    output reg  [DRAIN-1:0]      out_valid,
    output reg  [DRAIN*2*AW-1:0] out_pairs
);
    localparam LANES = 2 * M - 1;
    // Round-robin writes and reads keep the banks' levels within one of
    // each other, so DEPTH pairs need ceil(DEPTH / LANES) per bank; a power
    // of two lets the bank pointers wrap by themselves.
    localparam BW = (DEPTH + LANES - 1) / LANES > 1 ? $clog2((DEPTH + LANES - 1) / LANES) : 1;
    localparam BANK_DEPTH = 1 << BW;
    localparam LW = LANES > 1 ? $clog2(LANES) : 1;
    localparam CW = $clog2(DEPTH + 1);

    reg [BW-1:0] write_row [0:LANES-1];
    reg [LW-1:0] write_bank, read_bank;
    reg [CW-1:0] level;

    // (a + b) mod LANES for a, b < LANES: one compare and subtract, no divider.
    function [LW:0] wrap(input [LW:0] sum);
        wrap = sum >= LANES ? sum - LANES : sum;
    endfunction

    // Where each hit goes: its rank among this cycle's hits.
    reg [LANES*(LW+1)-1:0] ranks;  // hit k's rank at bits k*(LW+1)
    reg [LW:0] taken;
    integer k, b, d;
    always @* begin
        taken = 0;
        for (k = 0; k < LANES; k = k + 1) begin
            ranks[k*(LW+1) +: LW+1] = taken;
            taken = taken + hits[k];
        end
    end
    assign room = level + taken <= DEPTH;
    wire [LW:0] drained = drain_ready ? ((level < DRAIN) ? level : DRAIN) : 0;

    // Each bank is a simple dual-port memory: one write, one read a cycle.
    wire [2*AW-1:0] bank_out [0:LANES-1];
    wire [LANES-1:0] bank_write;
    reg  [BW-1:0] read_row [0:LANES-1];
    genvar g;
    generate
        for (g = 0; g < LANES; g = g + 1) begin : g_bank
            reg [2*AW-1:0] cells [0:BANK_DEPTH-1];
            reg            write;
            reg [2*AW-1:0] data;
            integer l;
            always @* begin
                write = 1'b0;
                data = 0;
                for (l = 0; l < LANES; l = l + 1) begin
                    if (hits[l] && room && wrap(write_bank + ranks[l*(LW+1) +: LW+1]) == g) begin
                        write = 1'b1;
                        data = {row, first + l[AW-1:0]};
                    end
                end
            end
            always @(posedge clk) if (write) cells[write_row[g]] <= data;
            assign bank_out[g] = cells[read_row[g]];
            assign bank_write[g] = write;
        end
    endgenerate

    always @(posedge clk) begin
        if (clear) begin
            write_bank <= 0;
            read_bank <= 0;
            level <= 0;
            for (b = 0; b < LANES; b = b + 1) begin
                write_row[b] <= 0;
                read_row[b] <= 0;
            end
        end else begin
            for (b = 0; b < LANES; b = b + 1) begin
                if (bank_write[b]) write_row[b] <= write_row[b] + 1;
            end
            if (room) write_bank <= wrap(write_bank + taken);
            for (d = 0; d < DRAIN; d = d + 1) begin
                b = wrap(read_bank + d);
                out_valid[d] <= d < drained;
                out_pairs[d*2*AW +: 2*AW] <= bank_out[b];
                if (d < drained) read_row[b] <= read_row[b] + 1;
            end
            read_bank <= wrap(read_bank + drained);
            level <= level + (room ? taken : 0) - drained;
        end
    end
endmodule
