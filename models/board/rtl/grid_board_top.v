// The whole grid board (docs/grid_board.md): the seed's host side
// (board_host.v: register bus, box store writes, pair FIFO, pair buffer,
// controller), the binning sequencer with its cell memory
// (grid_sequencer.v, grid_cell_memory.v), the cell loader and the
// double-buffered cell buffer, the seed's 2m-1 compare lanes with the
// one-cell filter behind them, and the boxes in six SSRAM banks. It follows
// GridClockedEngine (models/grid_clocked_engine) edge for edge: the same
// pairs in the same order, the same CYCLES, STALLS, TOTAL_PAIRS, PAIR_COUNT,
// STATUS and grid registers (tests/rtl/grid_board_lockstep_test.cpp).
// Register map version 3, board variant 1 (ID 0xCD7B1003): the seed's map
// and the grid registers at 0x60 to 0x88.
//
// The host bus is the seed's (collision_board_top.v): the coordinate windows
// and the delta stream write the box store in SSRAM through ssram_we, the
// pair buffer window reads the pairs. The SSRAM answers in the cycle of its
// address (ssram_rdata follows ssram_addr); its LAT read stages are the
// registers here, clocked with the slots (a ZBT SSRAM's clock enable), as the
// model's SSRAM is held by a stall.
//
// A slot issued at an edge: in the cell sweep the row and columns are cell
// buffer positions of the half the lanes read, in the large sweep the row is
// the streamed box (the sequencer's row register) and the columns the
// tile's positions in half 0. The cell buffer's entries carry each box's
// index and first cells, delayed beside the lanes' compare stages to the
// one-cell filter (cells) and to the pair FIFO, which takes each lane's
// pair as {min, max} of the two indices.
//
// Where it departs from the model, besides collision_board_top.v's list
// (one box bank, the list pair format, one pair a cycle, no injected error):
//  - One box a slot from six SSRAM banks (q = 1): board.ssram_banks 6.
//  - The cell memory is the sequencer's register files (grid_sequencer.v),
//    of 2^EAW cell entries; GRID_ENTRY_CAPACITY reads what they hold.
//  - The swept cell's coordinates come from its number by a division by the
//    grid's dims, once a slot (the model keeps them from the scan).
module grid_board_top #(
    parameter M = 2,                 // 2m-1 lanes
    parameter AW = 9,                // 2^AW boxes in the box store
    parameter FLOAT = 1,             // 1: float32; 0: unsigned fixed point of WIDTH bits
    parameter WIDTH = 32,
    parameter COMPARE_LATENCY = 2,
    parameter FIFO_DEPTH = 512,      // pairs (>= 2m-1)
    parameter BUFFER_DEPTH = 512,    // pairs the pair buffer holds before an overflow pause
    parameter LAT = 2,               // SSRAM read latency in slots
    // The grid, as built (board.grid.*):
    parameter DIMS = 0,              // cells a side, 0: chosen at START from the boxes
    parameter [31:0] CELL_SIZE = 0,  // binary32 bits of the fixed cell size, 0: fitted
    parameter CELL_CAPACITY = 512,   // boxes a cell list and the cell buffer hold
    parameter MAX_SPAN = 8,          // cells a binned box may cover
    parameter ENTRY_CAPACITY = 4096  // cell entries the cell memory holds
) (
    input  wire              clk,
    input  wire              reset,     // synchronous: as ABORT, and clears the registers
    // host register bus
    input  wire [27:0]       addr,
    input  wire [31:0]       wdata,
    input  wire              we,
    input  wire              re,
    output wire [31:0]       rdata,
    output wire              rvalid,
    output wire              irq,
    // six SSRAM banks, one shared address, answering in the address's cycle
    output wire [AW-1:0]     ssram_addr,
    output wire              ssram_re,
    output wire [5:0]        ssram_we,
    output wire [6*32-1:0]   ssram_wdata,
    input  wire [6*32-1:0]   ssram_rdata
);
    // The largest grid the board builds: DIMS, or the automatic grid of 2^AW boxes.
    function automatic integer grid_cells_for(input integer dims, input integer boxes);
        integer g;
        begin
            g = dims;
            if (g == 0) begin
                g = 1;
                while (g < 256 && 16 * (g + 1) * (g + 1) * (g + 1) <= boxes) g = g + 1;
            end
            grid_cells_for = g * g * g;
        end
    endfunction
    localparam LANES = 2 * M - 1;
    localparam D = 1 + COMPARE_LATENCY;           // block RAM stage + compare stages
    // A cell never holds more than the 2^AW boxes there are: cells of more
    // are cells of 2^AW (the same counts, tiles and buffer).
    localparam HELD = CELL_CAPACITY < (1 << AW) ? CELL_CAPACITY : (1 << AW);
    localparam CAW = $clog2(HELD);
    localparam CELLS = grid_cells_for(DIMS, 1 << AW);
    localparam CW = CELLS > 4 ? $clog2(CELLS) : 2;
    localparam EAW = $clog2(ENTRY_CAPACITY + 1) > AW ? $clog2(ENTRY_CAPACITY + 1) : AW + 1;
    localparam EW = 24 + AW + 6 * WIDTH;          // a cell buffer entry: first cells, index, coordinates
    localparam BAW = BUFFER_DEPTH > 1 ? $clog2(BUFFER_DEPTH) : 1;
    localparam [1:0] BUBBLE = 0, WINDOW = 1;
    localparam [3:0] PASS_LARGE = 4'd7, PASS_DONE = 4'd8;

    // ------------------------------------------------------------------
    // The host side.
    wire [4:0] state;
    wire [63:0] cycles, stalls;
    wire enable;            // the pipeline advances this edge (a slot)
    wire start_go, resume_go, done_now;
    wire [11:0] offset;
    wire [31:0] object_count;
    wire [5:0] store_we;
    wire [AW-1:0] store_index;
    wire [6*32-1:0] store_data;
    wire [LANES-1:0] kept_hits;
    wire [LANES-1:0] pushed_hits;
    wire out_valid;
    wire [2*AW-1:0] out_pair;
    wire [$clog2(FIFO_DEPTH + 1)-1:0] fifo_level;
    wire [BAW:0] buffered;                  // PAIR_COUNT
    wire [63:0] total_pairs;
    wire src_sweeping;
    reg [31:0] grid_register;
    reg [1:0] kind_q [0:D-1];
    wire [AW-1:0] pair_row;
    wire [LANES*AW-1:0] pair_columns;
    board_host #(.M(M), .AW(AW), .FIFO_DEPTH(FIFO_DEPTH), .FIFO_DISTRIBUTED(0), .BUFFER_DEPTH(BUFFER_DEPTH),
                 .LISTED(1), .ID_VALUE(32'hCD7B_1003), .FORMAT_VALUE(FLOAT != 0 ? 0 : WIDTH),
                 .TILE_BOXES_VALUE(0), .TILE_TIMING_VALUE((LAT & 32'hFFFF) | (32'd1 << 16))) host (
        .clk(clk), .reset(reset), .addr(addr), .wdata(wdata), .we(we), .re(re), .rdata(rdata), .rvalid(rvalid),
        .irq(irq), .offset(offset), .top_register(grid_register), .store_we(store_we), .store_index(store_index),
        .store_data(store_data), .start_go(start_go), .resume_go(resume_go), .enable(enable), .state(state),
        .cycles(cycles), .stalls(stalls), .object_count(object_count), .done_now(done_now),
        .sweeping(src_sweeping), .leaving(kind_q[D-1]), .lane_hits(kept_hits),
        .lane_hits_next({LANES{1'b0}}), .pair_row(pair_row),
        .pair_first({AW{1'b0}}), .pair_columns(pair_columns), .pushed_hits(pushed_hits), .out_valid(out_valid),
        .out_pair(out_pair), .fifo_level(fifo_level), .buffered(buffered), .total_pairs(total_pairs));

    // ------------------------------------------------------------------
    // The box store: the host's writes, else the sequencer's and the
    // loader's reads; its read stages held with the slots.
    wire seq_re, loader_re;
    wire [AW-1:0] seq_addr, loader_addr;
    wire [AW-1:0] read_addr = loader_re ? loader_addr : seq_addr;
    assign ssram_we = store_we;
    assign ssram_addr = store_we != 0 ? store_index : read_addr;
    assign ssram_re = seq_re | loader_re;
    assign ssram_wdata = store_data;
    wire [6*WIDTH-1:0] answer;              // the six words, WIDTH bits each
    genvar b;
    generate
        for (b = 0; b < 6; b = b + 1) begin : g_bank
            assign answer[b*WIDTH +: WIDTH] = ssram_rdata[b*32 +: WIDTH];
        end
    endgenerate
    wire [6*WIDTH-1:0] box_words;
    slot_delay #(.W(6 * WIDTH), .STAGES(LAT)) read_stages (.clk(clk), .enable(enable), .d(answer), .q(box_words));

    // ------------------------------------------------------------------
    // The sequencer, the cell loader and the cell buffer.
    wire load_start, load_due, load_half, load_done, sweep_half, entry_re, loader_busy;
    wire [CAW:0] load_count;
    wire [EAW-1:0] load_first, entry_addr;
    wire [AW-1:0] entry_word;
    wire [95:0] grid_lo, grid_scale;
    wire [8:0] grid_dims;
    wire [6*WIDTH-1:0] stream_words;
    wire [1:0] slot_kind;
    wire [31:0] window_row, window_column;
    wire [7:0] window_lanes;
    wire [3:0] pass;
    wire [AW:0] seq_box, seq_tile, large_boxes, overflow_boxes, excluded_boxes;
    wire [CW-1:0] cell_number;
    wire seq_waiting;
    wire [31:0] last_row, last_column;
    wire [7:0] last_lanes;
    wire [EAW:0] cell_entries;
    wire [CW:0] busy_cells;
    wire [47:0] slots;
    localparam [31:0] ENTRIES = ENTRY_CAPACITY, CAPACITY_CELLS = HELD, DIMS_SETTING = DIMS,
                      SPAN_SETTING = MAX_SPAN;
    grid_sequencer #(.FLOAT(FLOAT), .WIDTH(WIDTH), .AW(AW), .LAT(LAT), .M(M), .CAW(CAW), .CW(CW), .EAW(EAW),
                     .SPAN(MAX_SPAN)) sequencer (
        .clk(clk), .reset(reset), .start(start_go), .enable(enable), .objects(object_count[AW:0]),
        .dims_setting(DIMS_SETTING[8:0]), .cell_size(CELL_SIZE), .capacity(CAPACITY_CELLS[CAW:0]),
        .max_span(SPAN_SETTING[6:0]), .entry_capacity(ENTRIES[EAW:0]),
        .box_re(seq_re), .box_addr(seq_addr), .box_words(box_words),
        .load_start(load_start), .load_due(load_due), .load_half(load_half), .load_count(load_count),
        .load_first(load_first), .load_done(load_done), .entry_addr(entry_addr), .entry_word(entry_word),
        .grid_lo(grid_lo), .grid_scale(grid_scale), .grid_dims(grid_dims), .stream_words(stream_words),
        .slot_kind(slot_kind), .window_row(window_row), .window_column(window_column), .window_lanes(window_lanes),
        .sweep_half(sweep_half), .pass(pass), .box(seq_box), .cell_number(cell_number), .tile(seq_tile),
        .waiting(seq_waiting), .last_row(last_row), .last_column(last_column), .last_lanes(last_lanes),
        .large_boxes(large_boxes), .overflow_boxes(overflow_boxes), .excluded_boxes(excluded_boxes),
        .cell_entries(cell_entries), .busy_cells(busy_cells), .slots(slots));
    wire write;
    wire write_half;
    wire [CAW-1:0] write_addr;
    wire [EW-1:0] write_data;
    cell_loader #(.FLOAT(FLOAT), .WIDTH(WIDTH), .AW(AW), .EAW(EAW), .CAW(CAW), .LAT(LAT)) loader (
        .clk(clk), .enable(enable), .clear(start_go), .start(load_start), .half(load_half), .count(load_count),
        .first_entry(load_first), .lo(grid_lo), .scale(grid_scale), .dims(grid_dims),
        .entry_re(entry_re), .entry_addr(entry_addr), .entry_word(entry_word),
        .box_re(loader_re), .box_addr(loader_addr), .box_words(box_words),
        .write(write), .write_half(write_half), .write_addr(write_addr), .write_data(write_data),
        .busy(loader_busy), .done(load_done));

    // The slot this edge issues: what the lockstep check and the waveforms read.
    wire src_window = slot_kind == WINDOW;
    wire [AW-1:0] src_row = window_row[AW-1:0];        // a cell holds at most 2^AW boxes
    wire [AW-1:0] src_first = window_column[AW-1:0];
    wire [LANES-1:0] src_valid;
    genvar k;
    generate
        for (k = 0; k < LANES; k = k + 1) begin : g_valid
            assign src_valid[k] = src_window && window_lanes > k;
        end
    endgenerate
    assign src_sweeping = pass != PASS_DONE;

    // Port 0 reads the row's position, port k + 1 lane k's column.
    wire [2*M*CAW-1:0] read_ports;
    wire [2*M*EW-1:0] entries;
    generate
        for (k = 0; k < 2 * M; k = k + 1) begin : g_port
            wire [31:0] position = k == 0 ? window_row : window_column + k - 1;
            assign read_ports[k*CAW +: CAW] = position[CAW-1:0];
        end
    endgenerate
    cell_buffer #(.M(M), .EW(EW), .CAW(CAW)) cells (
        .clk(clk), .enable(enable), .read_half(sweep_half), .read_addr(read_ports), .read_data(entries),
        .write(write), .write_half(write_half), .write_addr(write_addr), .write_data(write_data));

    // ------------------------------------------------------------------
    // Stage 0 (with the block RAM outputs): the slot's kind, its valid lanes,
    // whether it streams a box (large sweep) and that box's words and index.
    reg [LANES-1:0] valid_q;
    reg large_q;
    reg [6*WIDTH-1:0] stream_q;
    reg [AW-1:0] stream_index_q;
    integer s;
    always @(posedge clk) begin
        if (start_go) begin
            for (s = 0; s < D; s = s + 1) kind_q[s] <= BUBBLE;
            valid_q <= 0;
        end else if (enable) begin
            kind_q[0] <= slot_kind;
            valid_q <= src_valid;
            large_q <= pass == PASS_LARGE;
            stream_q <= stream_words;
            stream_index_q <= window_row[AW-1:0];
            for (s = 1; s < D; s = s + 1) kind_q[s] <= kind_q[s-1];
        end
    end
    // The swept cell's coordinates (cell_number is the slot's from stage 0 on).
    wire [8:0] dims_now = grid_dims == 0 ? 9'd1 : grid_dims;
    wire [31:0] cell_wide = {{(32-CW){1'b0}}, cell_number};
    wire [31:0] cell_row = cell_wide / {23'b0, dims_now};
    wire [31:0] cell_x = cell_wide % {23'b0, dims_now};
    wire [31:0] cell_y = cell_row % {23'b0, dims_now};
    wire [31:0] cell_z = cell_row / {23'b0, dims_now};
    wire [23:0] here = {cell_z[7:0], cell_y[7:0], cell_x[7:0]};

    // The lanes: the row is port 0's entry in the cell sweep, the streamed box in the large one.
    wire [EW-1:0] row_entry = entries[0 +: EW];
    wire [6*WIDTH-1:0] row_box = large_q ? stream_q : row_entry[6*WIDTH-1:0];
    wire [AW-1:0] row_index = large_q ? stream_index_q : row_entry[6*WIDTH +: AW];
    wire [LANES-1:0] lane_hits;
    // What they become at the next slot: unused, as the one-cell filter
    // stands between the lanes and the pair FIFO, which counts its own cycle's.
    wire [LANES-1:0] lane_hits_next;
    wire [LANES*24-1:0] column_first;
    wire [LANES*AW-1:0] column_index;
    generate
        for (k = 0; k < LANES; k = k + 1) begin : g_lane
            wire [EW-1:0] column_entry = entries[(k+1)*EW +: EW];
            assign column_first[k*24 +: 24] = column_entry[EW-1 -: 24];
            assign column_index[k*AW +: AW] = column_entry[6*WIDTH +: AW];
            compare_lane #(.FLOAT(FLOAT), .WIDTH(WIDTH), .LATENCY(COMPARE_LATENCY)) lane (
                .clk(clk), .enable(enable), .valid_in(valid_q[k]), .box_i(row_box),
                .box_j(column_entry[6*WIDTH-1:0]), .hit(lane_hits[k]), .hit_next(lane_hits_next[k]));
        end
    endgenerate

    // What the filter and the pair FIFO need of the slot, delayed beside the compare stages.
    localparam MW = 1 + 24 + 24 + AW + LANES * (24 + AW);
    wire [MW-1:0] meta_in = {large_q, here, row_entry[EW-1 -: 24], row_index, column_first, column_index};
    wire [MW-1:0] meta;
    slot_delay #(.W(MW), .STAGES(COMPARE_LATENCY)) meta_stages (.clk(clk), .enable(enable), .d(meta_in), .q(meta));
    wire meta_large = meta[MW-1];
    wire [23:0] meta_here = meta[MW-2 -: 24];
    wire [23:0] meta_row_first = meta[MW-26 -: 24];
    assign pair_row = meta[LANES*(24+AW) +: AW];
    wire [LANES*24-1:0] meta_column_first = meta[LANES*AW +: LANES*24];
    assign pair_columns = meta[0 +: LANES*AW];
    wire [LANES-1:0] home_hits;
    home_cell_filter #(.LANES(LANES)) filter (
        .hits(lane_hits), .here(meta_here), .row_first(meta_row_first), .column_first(meta_column_first),
        .kept(home_hits));
    assign kept_hits = meta_large ? lane_hits : home_hits;

    // ------------------------------------------------------------------
    // The grid registers: as built, and the last sweep's, kept when it is done.
    reg [31:0] sweep_dims, sweep_large, sweep_overflow, sweep_excluded, sweep_busy;
    reg [63:0] sweep_entries, sweep_slots;
    always @(posedge clk) begin
        if (reset) begin
            sweep_dims <= 0;
            sweep_large <= 0;
            sweep_overflow <= 0;
            sweep_excluded <= 0;
            sweep_entries <= 0;
            sweep_busy <= 0;
            sweep_slots <= 0;
        end else if (done_now) begin
            // A sweep of fewer than two boxes builds no grid.
            sweep_dims <= object_count < 2 ? 32'd0 : {23'b0, grid_dims};
            sweep_large <= {{(31-AW){1'b0}}, large_boxes};
            sweep_overflow <= {{(31-AW){1'b0}}, overflow_boxes};
            sweep_excluded <= {{(31-AW){1'b0}}, excluded_boxes};
            sweep_entries <= {{(63-EAW){1'b0}}, cell_entries};
            sweep_busy <= {{(31-CW){1'b0}}, busy_cells};
            sweep_slots <= {16'b0, slots};
        end
    end
    always @* begin
        case (offset)
            12'h060: grid_register = DIMS;
            12'h064: grid_register = CELL_CAPACITY;
            12'h068: grid_register = MAX_SPAN;
            12'h06C: grid_register = CELL_SIZE;
            12'h070: grid_register = ENTRY_CAPACITY;
            12'h074: grid_register = sweep_dims;
            12'h078: grid_register = sweep_large;
            12'h07C: grid_register = sweep_overflow;
            12'h080: grid_register = sweep_entries[63:32] != 0 ? 32'hFFFF_FFFF : sweep_entries[31:0];
            12'h084: grid_register = sweep_busy;
            12'h088: grid_register = sweep_excluded;
            default: grid_register = 0;
        endcase
    end
endmodule

// STAGES registers clocked with the slots (none: a wire).
module slot_delay #(
    parameter W = 8,
    parameter STAGES = 1
) (
    input  wire         clk,
    input  wire         enable,
    input  wire [W-1:0] d,
    output wire [W-1:0] q
);
    generate
        if (STAGES == 0) begin : g_wire
            assign q = d;
        end else begin : g_stages
            reg [W-1:0] stage [0:STAGES-1];
            integer s;
            always @(posedge clk) if (enable) begin
                stage[0] <= d;
                for (s = 1; s < STAGES; s = s + 1) stage[s] <= stage[s-1];
            end
            assign q = stage[STAGES-1];
        end
    endgenerate
endmodule
