// The pair FIFO: takes a cycle's lane hits, all or none (the board holds
// the pipeline while the FIFO lacks room for all of a cycle's hits: the
// model's rule, counted in pairs), and hands one pair a cycle to the pair
// buffer in row-then-column order. A cycle with hits is stored as one entry,
// {row, first, hit mask}; the read side passes on the lowest hit of the head
// entry each cycle and moves to the next entry with its last. One write and
// one read a cycle, so the entries fit a simple dual-port memory whatever m
// is. LISTED = 1 (the grid board, whose lanes read boxes by cell buffer
// position): an entry keeps every lane's column index instead of the first,
// {row, columns, hit mask}, and a pair leaves as {min, max} of the row and
// its lane's column.
// Written for its clock as well as the model's cycles (which it keeps): the
// head entry is held in registers with its next pair found a cycle ahead
// (the memory reads the entry after it), no path runs through every lane in
// turn (hits counted by a tree of adds, the lowest isolated on the carry
// chain, its lane an OR of one-hot bits), the free places are kept beside
// the level so room is one compare, every count's next value is made both
// ways for the write to choose, and with COUNT_AHEAD the hits are counted a
// cycle before they arrive (docs/resources.md, "What the pieces reach").
module pair_collector #(
    parameter M = 8,
    parameter AW = 9,
    parameter DEPTH = 512,   // pairs (and entries: an entry holds at least one)
    parameter DISTRIBUTED = 0, // 1: entries in LUTs (distributed RAM), 0: in block RAM
    parameter DRAIN_FIRST = 0, // 1: the pair leaving this cycle frees its place for this
                               // cycle's hits (the C++ model drains before it pushes)
    parameter LISTED = 0,      // 1: each lane's column given (columns), pairs as {min, max}
    parameter COUNT_AHEAD = 0  // 1: the hits counted a cycle ahead, from hits_next (lanes of
                               // compare latency 2 or more), so room waits on no count
) (
    input  wire            clk,
    input  wire            clear,
    input  wire [2*M-2:0]  hits,         // this cycle's hits, none unless push
    // COUNT_AHEAD: what the lanes' hits become at the next hits_step edge,
    // and whether this cycle's are pushed (hits is zero otherwise).
    input  wire [2*M-2:0]  hits_next,
    input  wire            hits_step,
    input  wire            push,
    output wire [$clog2(2*M)-1:0] pushed,  // pairs in this cycle's hits (at most 2M-1)
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
    localparam EW = LISTED ? AW + LANES * AW + LANES : 2 * AW + LANES;  // entry: row, first or columns, mask

    reg [PW-1:0] write_at;
    reg [PW-1:0] read_after, read_later;  // the head's next two addresses (wrapped)
    reg [CW-1:0] pairs;        // pairs held: the model's FIFO level
    reg [CW-1:0] held;         // entries held

    reg [CW-1:0] free;         // DEPTH - pairs, kept beside it: room is one compare
    // Pairs in this cycle's hits: a balanced tree of adds (a chain through
    // every lane was the longest path once the read side was flattened), over
    // this cycle's hits or, COUNT_AHEAD, over the next and registered with them.
    wire [LW:0] taken, offered;  // offered: taken before the push gates it (COUNT_AHEAD)
    reg [LW:0] hit_count;
    reg [LW:0] sums [0:LANES-1];
    integer k, w;
    always @* begin
        for (k = 0; k < LANES; k = k + 1) sums[k] = {{LW{1'b0}}, COUNT_AHEAD != 0 ? hits_next[k] : hits[k]};
        for (w = 1; w < LANES; w = w * 2)
            for (k = 0; k + w < LANES; k = k + 2 * w) sums[k] = sums[k] + sums[k + w];
        hit_count = sums[0];
    end
    generate
        if (COUNT_AHEAD != 0) begin : g_ahead
            reg [LW:0] counted_ahead;  // the lanes' hits' count, a register beside theirs
            always @(posedge clk) if (hits_step) counted_ahead <= hit_count;
            assign offered = counted_ahead;
            assign taken = push ? counted_ahead : {(LW+1){1'b0}};
        end else begin : g_now
            assign offered = hit_count;
            assign taken = hit_count;
        end
    endgenerate
    assign pushed = taken[$clog2(2*M)-1:0];
    wire take;
    // The compare's operands at one width (each extended by a bit at least).
    localparam XW = (CW > LW + 1 ? CW : LW + 1) + 1;
    wire [XW-1:0] offered_x = {{(XW-LW-1){1'b0}}, offered};
    wire [XW-1:0] free_x = {{(XW-CW){1'b0}}, free};
    // Room counts the pair leaving this cycle when DRAIN_FIRST is set: both
    // ways compared from registers (counted ahead), the take chooses at the
    // end, and no push needs none.
    wire fits = offered_x <= free_x;
    wire fits_taking = offered_x <= free_x + 1'b1;
    assign room = (COUNT_AHEAD != 0 && !push) || (DRAIN_FIRST != 0 && take ? fits_taking : fits);
    wire write = room && (|hits);
    // The next level either way, chosen by write at the end of the path.
    wire [CW-1:0] pairs_written = pairs + taken - take, pairs_kept = pairs - take;
    wire [CW-1:0] free_written = free - taken + take, free_kept = free + take;
    wire advance;  // the head's last pair leaves
    wire [CW-1:0] held_written = held + 1'b1 - advance, held_kept = held - advance;
    wire [EW-1:0] entry;

    // The head entry lives in registers, with its hits not yet passed on and
    // the lowest of them (one-hot and its lane) found when they change, a
    // cycle ahead of its use; the memory meanwhile reads the entry after it.
    // So a pair leaves from registers, and nothing runs from the memory's
    // output through the lanes' search into its address (the FIFO's longest
    // path as first written). The lowest hit is isolated on the carry chain
    // (x & -x) and its lane is an OR of the one-hot bits.
    reg [EW-1:0] head;               // the head entry as written
    reg [LANES-1:0] left;            // its hits not yet passed on
    reg [LANES-1:0] bit_taken;       // the lowest of them, one-hot
    reg [LW-1:0] lane;               // its lane
    reg last;                        // it is the only one left: the entry leaves with it
    wire [EW-1:0] after_head;        // entries[read_after]: the next head
    // Each entry is stored with its lowest hit's lane and whether that hit is
    // its only one, found as it is written: the entry after the head comes
    // out of the memory with them, and nothing runs from the memory's output
    // through a search of its lanes (the longest path at large m, once the
    // memory's clock-to-out is in it).
    // A held head has a hit left (an entry holds one at least and leaves
    // with its last), so neither needs the mask.
    assign take = held != 0 && drain_ready;
    assign advance = take && last;
    wire load_written = write && (held == 0 || (held == 1 && advance));  // the entry written is the next head
    wire load_after = advance && held != 1;                              // the one after the head is
    // The next hits left, lowest and last from each source at once, chosen
    // at the end: whether the write is the next head waits on room, and
    // room on the count.
    wire [LANES-1:0] mask_written = hits, mask_after = after_head[LANES-1:0], mask_kept = left & ~bit_taken;
    wire [LANES-1:0] bit_written, bit_after, bit_kept;
    wire [LW-1:0] lane_written, lane_after, lane_kept;
    wire last_written, last_after, last_kept;
    lowest_hit #(.LANES(LANES), .LW(LW)) lowest_written (
        .mask(mask_written), .one_hot(bit_written), .lane(lane_written), .only(last_written));
    genvar d;
    generate
        for (d = 0; d < LANES; d = d + 1) begin : g_after_bit
            assign bit_after[d] = lane_after == d;
        end
    endgenerate
    lowest_hit #(.LANES(LANES), .LW(LW)) lowest_kept (
        .mask(mask_kept), .one_hot(bit_kept), .lane(lane_kept), .only(last_kept));
    assign level = pairs;
    wire [PW-1:0] read_from = advance ? read_later : read_after;  // the memory's read: after the next head

    // The head's pair for `lane`: its row and column.
    wire [AW-1:0] head_row = head[EW-1 -: AW];
    wire [AW-1:0] head_column;
    wire [2*AW-1:0] head_pair;
    generate
        if (LISTED) begin : g_listed
            assign entry = {row, columns, hits};
            // The taken lane's column: an AND-OR over the one-hot bit, as flat as the lane number.
            reg [AW-1:0] column_taken;
            integer c;
            always @* begin
                column_taken = 0;
                for (c = 0; c < LANES; c = c + 1) column_taken = column_taken | ({AW{bit_taken[c]}} & head[LANES + c * AW +: AW]);
            end
            assign head_column = column_taken;
            assign head_pair = head_row < head_column ? {head_row, head_column} : {head_column, head_row};
        end else begin : g_consecutive
            assign entry = {row, first, hits};
            assign head_column = head[LANES +: AW] + lane;
            assign head_pair = {head_row, head_column};
        end
    endgenerate

    generate
        if (LANES > 1) begin : g_stored_lowest
            pair_fifo_memory #(.W(EW + LW + 1), .DEPTH(DEPTH), .AW(PW), .DISTRIBUTED(DISTRIBUTED)) entries (
                .clk(clk), .write(write), .write_at(write_at), .data({entry, lane_written, last_written}),
                .read_at(read_from), .q({after_head, lane_after, last_after}));
        end else begin : g_one_lane
            // One lane: an entry's one hit is lane 0's, and the last.
            pair_fifo_memory #(.W(EW), .DEPTH(DEPTH), .AW(PW), .DISTRIBUTED(DISTRIBUTED)) entries (
                .clk(clk), .write(write), .write_at(write_at), .data(entry), .read_at(read_from), .q(after_head));
            assign lane_after = 0;
            assign last_after = 1;
        end
    endgenerate

    always @(posedge clk) begin
        out_valid <= take;
        if (take) out_pair <= head_pair;
        if (load_written || load_after) head <= load_written ? entry : after_head;
        if (load_written) begin
            left <= mask_written;
            bit_taken <= bit_written;
            lane <= lane_written;
            last <= last_written;
        end else if (load_after) begin
            left <= mask_after;
            bit_taken <= bit_after;
            lane <= lane_after;
            last <= last_after;
        end else if (take) begin
            left <= mask_kept;
            bit_taken <= bit_kept;
            lane <= lane_kept;
            last <= last_kept;
        end
        if (clear) begin
            write_at <= 0;
            read_after <= DEPTH > 1 ? 1 : 0;
            read_later <= DEPTH > 2 ? 2 : 0;
            pairs <= 0;
            free <= DEPTH;
            held <= 0;
        end else begin
            if (write) write_at <= write_at + 1 == DEPTH ? 0 : write_at + 1;
            if (advance) begin
                read_after <= read_later;
                read_later <= read_later + 1 == DEPTH ? 0 : read_later + 1;
            end
            pairs <= write ? pairs_written : pairs_kept;
            free <= write ? free_written : free_kept;
            held <= write ? held_written : held_kept;
        end
    end
endmodule

// The lowest set bit of a mask (isolated on the carry chain, x & -x), its
// lane (an OR of the one-hot bits: each lane-number bit a balanced OR), and
// whether it is the only one.
module lowest_hit #(
    parameter LANES = 15,
    parameter LW = 4
) (
    input  wire [LANES-1:0] mask,
    output wire [LANES-1:0] one_hot,
    output reg  [LW-1:0]    lane,
    output wire             only
);
    assign one_hot = mask & (~mask + 1'b1);
    assign only = (mask & ~one_hot) == 0;
    integer l;
    always @* begin
        lane = 0;
        for (l = 0; l < LANES; l = l + 1) lane = lane | ({LW{one_hot[l]}} & l[LW-1:0]);
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
