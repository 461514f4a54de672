// The pair FIFO: takes a cycle's lane hits, all or none (the board holds
// the pipeline while the FIFO lacks room for all of a cycle's hits: the
// model's rule, counted in pairs), and hands one pair a cycle to the pair
// buffer in row-then-column order. A cycle with hits is stored as one entry,
// {row, first, hit count, hit mask}; the read side takes the lowest set bit
// of the head entry's mask each cycle and clears it, and moves to the next
// entry with its count's last pair. One write and one read a cycle, so the
// entries fit a simple dual-port memory whatever m is.
// LISTED = 1 (the grid board, whose lanes read boxes by cell buffer
// position): an entry keeps every lane's column index instead of the first,
// {row, columns, hit count, hit mask}, and a pair leaves as {min, max} of the
// row and its lane's column.
// Written for its clock as well as the model's cycles (which it keeps): no
// path runs through every lane in turn (the hits counted by a tree of adds,
// the lowest hit isolated on the carry chain, its lane an OR of one-hot
// bits), the free places kept beside the level so room is one compare, and
// every count's next value made both ways and chosen by the write.
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
    localparam PW = DEPTH > 1 ? $clog2(DEPTH) : 1;  // a one-pair FIFO (m = 1) still has an address bit
    localparam CW = $clog2(DEPTH + 1);
    localparam LW = LANES > 1 ? $clog2(LANES) : 1;
    // An entry: row, first or columns, its hits' count (from the write side's
    // room check, so the read side knows its last pair without scanning the
    // mask; with one lane an entry is one pair), hit mask.
    localparam NB = LANES > 1 ? LANES + LW + 1 : LANES;  // where the first or columns begin
    localparam EW = LISTED ? AW + LANES * AW + NB : 2 * AW + NB;

    reg [PW-1:0] write_at, read_at;
    reg [CW-1:0] pairs;        // pairs held: the model's FIFO level
    reg [CW-1:0] held;         // entries held
    wire [EW-1:0] head;        // entries[read_at], read synchronously
    reg [LANES-1:0] consumed;  // the head's hits already passed on
    reg [LW:0] passed;         // how many: the head's last pair is its count's
    reg [PW-1:0] read_after;   // read_at's successor, wrapped

    reg [CW-1:0] free;         // DEPTH - pairs, kept beside it: room is one compare
    // Pairs in this cycle's hits: a balanced tree of adds (a chain through
    // every lane was the longest path once the read side was flattened).
    reg [LW:0] taken;
    reg [LW:0] sums [0:LANES-1];
    integer k, w;
    always @* begin
        for (k = 0; k < LANES; k = k + 1) sums[k] = {{LW{1'b0}}, hits[k]};
        for (w = 1; w < LANES; w = w * 2)
            for (k = 0; k + w < LANES; k = k + 2 * w) sums[k] = sums[k] + sums[k + w];
        taken = sums[0];
    end
    wire take;
    // The compare's operands at one width (each extended by a bit at least).
    localparam XW = (CW > LW + 1 ? CW : LW + 1) + 1;
    wire [XW-1:0] taken_x = {{(XW-LW-1){1'b0}}, taken};
    wire [XW-1:0] free_x = {{(XW-CW){1'b0}}, free};
    // Room counts the pair leaving this cycle when DRAIN_FIRST is set.
    generate
        if (DRAIN_FIRST) begin : g_drain_first
            assign room = taken_x <= free_x + {{(XW-1){1'b0}}, take};
        end else begin : g_push_first
            assign room = taken_x <= free_x;
        end
    endgenerate
    wire write = room && (|hits);
    // The next level either way, chosen by write at the end of the path.
    wire [CW-1:0] pairs_written = pairs + taken - take, pairs_kept = pairs - take;
    wire [CW-1:0] free_written = free - taken + take, free_kept = free + take;
    wire advance;  // the head's last pair leaves
    wire [CW-1:0] held_written = held + 1'b1 - advance, held_kept = held - advance;
    wire [EW-1:0] entry;

    // The lowest hit of the head entry not yet passed on: isolated with the
    // carry chain (x & -x), and its lane number an OR of the one-hot bits
    // (each number bit a balanced OR), not a priority chain through every
    // lane, which was the FIFO's longest path (docs/resources.md).
    wire [LANES-1:0] left = held != 0 ? head[LANES-1:0] & ~consumed : 0;
    wire [LANES-1:0] bit_taken = left & (~left + 1'b1);
    reg [LW-1:0] lane;
    integer l;
    always @* begin
        lane = 0;
        for (l = 0; l < LANES; l = l + 1) lane = lane | ({LW{bit_taken[l]}} & l[LW-1:0]);
    end
    // A held head has a hit left (an entry holds one at least and leaves
    // with its last), so neither needs the mask.
    assign take = held != 0 && drain_ready;
    wire [NB-1:0] counted;  // this cycle's hits and, with more than one lane, their count
    generate
        if (LANES > 1) begin : g_counted
            assign advance = take && passed + 1'b1 == head[LANES +: LW + 1];
            assign counted = {taken, hits};
        end else begin : g_single
            assign advance = take;
            assign counted = hits;
        end
    endgenerate
    assign level = pairs;
    wire [PW-1:0] read_next = advance ? read_after : read_at;

    // The head's pair for `lane`: its row and column.
    wire [AW-1:0] head_row = head[EW-1 -: AW];
    wire [AW-1:0] head_column;
    wire [2*AW-1:0] head_pair;
    generate
        if (LISTED) begin : g_listed
            assign entry = {row, columns, counted};
            // The taken lane's column: an AND-OR over the one-hot bit, as flat as the lane number.
            reg [AW-1:0] column_taken;
            integer c;
            always @* begin
                column_taken = 0;
                for (c = 0; c < LANES; c = c + 1) column_taken = column_taken | ({AW{bit_taken[c]}} & head[NB + c * AW +: AW]);
            end
            assign head_column = column_taken;
            assign head_pair = head_row < head_column ? {head_row, head_column} : {head_column, head_row};
        end else begin : g_consecutive
            assign entry = {row, first, counted};
            assign head_column = head[NB +: AW] + lane;
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
            read_after <= DEPTH > 1 ? 1 : 0;
            passed <= 0;
            pairs <= 0;
            free <= DEPTH;
            held <= 0;
            consumed <= 0;
        end else begin
            if (write) write_at <= write_at + 1 == DEPTH ? 0 : write_at + 1;
            read_at <= read_next;
            if (advance) read_after <= read_after + 1 == DEPTH ? 0 : read_after + 1;
            passed <= advance ? 0 : passed + take;
            pairs <= write ? pairs_written : pairs_kept;
            free <= write ? free_written : free_kept;
            held <= write ? held_written : held_kept;
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
