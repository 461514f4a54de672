// The pair FIFO: takes a cycle's lane hits, all or none (the board holds
// the pipeline while the FIFO lacks room for all of a cycle's hits: the
// model's rule, counted in pairs), and hands one pair a cycle to the pair
// buffer in row-then-column order. A cycle with hits is stored as one entry,
// {row, first, hit mask}; the read side takes the lowest set bit of the
// head entry's mask each cycle (a priority encoder) and clears it, and
// moves to the next entry when the mask is empty. One write and one read a
// cycle, so the entries fit a simple dual-port memory whatever m is.
// LISTED = 1 (the grid board, whose lanes read boxes by cell buffer
// position): an entry keeps every lane's column index instead of the first,
// {row, columns, hit mask}, and a pair leaves as {min, max} of the row and
// its lane's column.
module pair_collector #(
    parameter M = 8,
    parameter AW = 9,
    parameter DEPTH = 512,   // pairs (and entries: an entry holds at least one)
    parameter DISTRIBUTED = 0, // 1: entries in LUTs (distributed RAM), 0: in block RAM
    parameter DRAIN_FIRST = 0, // 1: the pair leaving this cycle frees its place for this
                               // cycle's hits (the C++ model drains before it pushes)
    parameter LISTED = 0       // 1: each lane's column given (columns), pairs as {min, max}
) (
    input  wire            clk,
    input  wire            clear,
    input  wire [2*M-2:0]  hits,
    input  wire [AW-1:0]   row,
    input  wire [AW-1:0]   first,
    input  wire [(2*M-1)*AW-1:0] columns,  // LISTED: lane k's column at k*AW
    input  wire            drain_ready,  // the pair buffer takes a pair
    output wire            room,         // this cycle's hits fit
    output reg             out_valid,
    output reg  [2*AW-1:0] out_pair,     // {row, column}
    output wire [$clog2(DEPTH+1)-1:0] level  // pairs held (before this cycle's move)
);
    localparam LANES = 2 * M - 1;
    localparam EW = LISTED ? AW + LANES * AW + LANES : 2 * AW + LANES;  // entry: row, first or columns, mask
    localparam PW = DEPTH > 1 ? $clog2(DEPTH) : 1;  // a one-pair FIFO (m = 1) still has an address bit
    localparam CW = $clog2(DEPTH + 1);
    localparam LW = LANES > 1 ? $clog2(LANES) : 1;

    reg [PW-1:0] write_at, read_at;
    reg [CW-1:0] pairs;        // pairs held: the model's FIFO level
    reg [CW-1:0] held;         // entries held
    wire [EW-1:0] head;        // entries[read_at], read synchronously
    reg [LANES-1:0] consumed;  // the head's hits already passed on

    // Pairs in this cycle's hits.
    reg [LW:0] taken;
    integer k;
    always @* begin
        taken = 0;
        for (k = 0; k < LANES; k = k + 1) taken = taken + hits[k];
    end
    wire take;
    // Room counts the pair leaving this cycle when DRAIN_FIRST is set.
    generate
        if (DRAIN_FIRST) begin : g_drain_first
            assign room = pairs + taken <= DEPTH + take;
        end else begin : g_push_first
            assign room = pairs + taken <= DEPTH;
        end
    endgenerate
    wire write = room && (|hits);
    wire [EW-1:0] entry;

    // The lowest hit of the head entry not yet passed on.
    wire [LANES-1:0] left = held != 0 ? head[LANES-1:0] & ~consumed : 0;
    reg [LW-1:0] lane;
    integer l;
    always @* begin
        lane = 0;
        for (l = LANES - 1; l >= 0; l = l - 1) if (left[l]) lane = l;
    end
    wire [LANES-1:0] bit_taken = {{(LANES-1){1'b0}}, 1'b1} << lane;
    assign take = (|left) && drain_ready;
    wire advance = take && (left & ~bit_taken) == 0;  // the head's last pair leaves
    assign level = pairs;
    wire [PW-1:0] read_next = advance ? (read_at + 1 == DEPTH ? 0 : read_at + 1) : read_at;

    // The head's pair for `lane`: its row and column.
    wire [AW-1:0] head_row = head[EW-1 -: AW];
    wire [AW-1:0] head_column;
    wire [2*AW-1:0] head_pair;
    generate
        if (LISTED) begin : g_listed
            assign entry = {row, columns, hits};
            assign head_column = head[LANES + lane * AW +: AW];
            assign head_pair = head_row < head_column ? {head_row, head_column} : {head_column, head_row};
        end else begin : g_consecutive
            assign entry = {row, first, hits};
            assign head_column = head[LANES +: AW] + lane;
            assign head_pair = {head_row, head_column};
        end
    endgenerate

    pair_fifo_memory #(.W(EW), .DEPTH(DEPTH), .AW(PW), .DISTRIBUTED(DISTRIBUTED)) entries (
        .clk(clk), .write(write), .write_at(write_at), .data(entry), .read_at(read_next), .q(head));

    always @(posedge clk) begin
        out_valid <= take;
        if (take) out_pair <= head_pair;
        if (clear) begin
            write_at <= 0;
            read_at <= 0;
            pairs <= 0;
            held <= 0;
            consumed <= 0;
        end else begin
            if (write) write_at <= write_at + 1 == DEPTH ? 0 : write_at + 1;
            read_at <= read_next;
            pairs <= pairs + (write ? taken : 0) - take;
            held <= held + write - advance;
            consumed <= advance ? 0 : take ? consumed | bit_taken : consumed;
        end
    end
endmodule

// The entries: one write and one synchronous read a cycle (the entry
// written in the same cycle passes through), in block RAM or in LUTs.
module pair_fifo_memory #(
    parameter W = 8,
    parameter DEPTH = 16,
    parameter AW = 4,
    parameter DISTRIBUTED = 0
) (
    input  wire          clk,
    input  wire          write,
    input  wire [AW-1:0] write_at,
    input  wire [W-1:0]  data,
    input  wire [AW-1:0] read_at,
    output reg  [W-1:0]  q
);
    generate
        if (DISTRIBUTED) begin : g_luts
            (* ram_style = "distributed" *) reg [W-1:0] cells [0:DEPTH-1];
            always @(posedge clk) begin
                if (write) cells[write_at] <= data;
                q <= write && write_at == read_at ? data : cells[read_at];
            end
        end else begin : g_block_ram
            (* ram_style = "block" *) reg [W-1:0] cells [0:DEPTH-1];
            always @(posedge clk) begin
                if (write) cells[write_at] <= data;
                q <= write && write_at == read_at ? data : cells[read_at];
            end
        end
    endgenerate
endmodule
