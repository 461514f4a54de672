// The whole collision board: host register bus, six coordinate memories,
// the address generator (or, on a tiled board, the tile walker and loader
// with the boxes in six SSRAM banks), 2m-1 compare lanes, the pair FIFO,
// the pair buffer and the controller. It follows the C++ BoardCore with the
// clocked engine (models/board/board_core.*, models/clocked_engine/) edge
// for edge: the same pairs in the same order, the same CYCLES, STALLS,
// TOTAL_PAIRS, PAIR_COUNT, STATUS and ERROR_CAUSE (tests/rtl checks it).
// The register bus, pair FIFO, pair buffer and controller are board_host
// (board_host.v), which the grid board's top shares.
// Register map version 3 (ID 0xCD7B0003): STATUS bit 4 INTERRUPT (the irq
// line: from done, overflow or an error until ACKNOWLEDGE, START, RESUME or
// ABORT), BOX_BANKS, HOST_BANK and PAIR_BANK.
//
// Cycle semantics (the model's ClockedEngine::step, per clock edge while
// running): a pause when the FIFO holds pairs and the pair buffer is full
// (the edge counts as a stall); otherwise one pair moves from the FIFO to
// the pair buffer, then the slot leaving the compare pipeline pushes its
// hits into the FIFO (all or none: no room holds the whole pipeline, a
// stall), then a new slot is issued. A slot issued at an edge reaches the
// FIFO 1 + COMPARE_LATENCY edges later (block RAM read, compare stages);
// the end marker follows the last window, so a sweep without stalls takes
// S(N,m) + L edges, L = COMPARE_LATENCY + 2. Edges after the end marker
// that only drain the FIFO count as stalls.
//
// The host bus: byte addresses of the model's address map
// (models/control_registers/control_registers.h), 28 bits: registers at
// 0x000_0000, coordinate memory c at 0x100_0000 * (c + 1) (box i at 4i,
// write-only here), the pair buffer at 0x700_0000 (pair k at 8k, first index
// in the low word), the delta stream at 0x900_0000. A read returns rdata
// with rvalid one cycle after re.
//
// Where it departs from the model (docs/rtl.md):
//  - PAIR_FORMAT takes only 0 (the list); counted and bitmap read-backs are
//    refused with kBadPairFormat, and kPairWindowFull cannot occur.
//  - One box bank only (BOX_BANKS is a localparam fixed at 1): no frame
//    pipelining. BOX_BANKS reads 1 and HOST_BANK 0; PAIR_BANK takes 0
//    (current) or 1 (previous; any other value is refused with
//    kBadPairBank), and with 1 it shows the previous pair buffer, which on a
//    one-bank board holds no pairs (PAIR_COUNT and PAIR_WORDS read 0, the
//    pair window reads 0), as the model's does.
//  - No injected board error (kInjectedError) and no fault hooks.
//  - Tiled boards read a box in one cycle (six SSRAM banks: cycles_per_box 1).
//  - A pair reaches the pair buffer's memory one edge after PAIR_COUNT
//    counts it (the collector's output register); the host reads the buffer
//    only once the board has stopped, so it never sees the difference.
//  - Unmapped reads return 0 (the model's bus answers with an error);
//    coordinate windows are write-only.
//  - The pair buffer is on chip (BUFFER_DEPTH pairs of block RAM); the
//    presets put it in an SSRAM bank. One pair moves a cycle (drain_per_cycle 1).
module collision_board_top #(
    parameter M = 2,                 // 2m-port coordinate memories, 2m-1 lanes
    parameter AW = 9,                // capacity: 2^AW boxes (block RAM, or SSRAM when tiled)
    parameter FLOAT = 1,             // 1: float32; 0: unsigned fixed point of WIDTH bits
    parameter WIDTH = 32,
    parameter COMPARE_LATENCY = 2,
    parameter FIFO_DEPTH = 512,      // pairs (>= 2m-1)
    parameter FIFO_DISTRIBUTED = 0,
    parameter BUFFER_DEPTH = 512,    // pairs the pair buffer holds before an overflow pause
    parameter TILE_BOXES = 0,        // 0: every box in block RAM; T > 0: SSRAM tiles of T boxes
    parameter TILE_LATENCY = 2       // SSRAM read latency in cycles (tiled boards)
) (
    input  wire              clk,
    input  wire              reset,     // synchronous: as ABORT, and clears the registers
    // host register bus
    input  wire [27:0]       addr,
    input  wire [31:0]       wdata,
    input  wire              we,
    input  wire              re,
    output reg  [31:0]       rdata,
    output reg               rvalid,
    output wire              irq,
    // six SSRAM banks (tiled boards; unused otherwise), one shared address
    output wire [AW-1:0]     ssram_addr,
    output wire              ssram_re,
    output wire [5:0]        ssram_we,
    output wire [6*32-1:0]   ssram_wdata,
    input  wire [6*32-1:0]   ssram_rdata
);
    localparam LANES = 2 * M - 1;
    localparam D = 1 + COMPARE_LATENCY;           // block RAM stage + compare stages
    localparam TILED = TILE_BOXES > 0;
    localparam TAW = TILE_BOXES > 1 ? $clog2(TILE_BOXES) : 1;
    localparam BAW = BUFFER_DEPTH > 1 ? $clog2(BUFFER_DEPTH) : 1;
    localparam [1:0] BUBBLE = 0, WINDOW = 1, END = 2;

    // ------------------------------------------------------------------
    // The host side (board_host.v): register bus, box store writes, pair
    // FIFO, pair buffer and controller.
    wire [4:0] state;
    wire [63:0] cycles, stalls;
    wire enable;            // the pipeline advances this edge (a slot)
    wire start_go, resume_go, done_now;
    wire [11:0] offset;                     // no registers of its own
    wire [31:0] object_count;
    wire [5:0] store_we;
    wire [AW-1:0] store_index;
    wire [6*32-1:0] store_data;
    wire [LANES-1:0] lane_hits;
    wire [LANES-1:0] lane_hits_next;
    wire [LANES-1:0] pushed_hits;
    wire out_valid;
    wire [2*AW-1:0] out_pair;
    wire [$clog2(FIFO_DEPTH + 1)-1:0] fifo_level;
    wire [BAW:0] buffered;                  // PAIR_COUNT
    wire [63:0] total_pairs;
    wire src_sweeping;
    reg [1:0] kind_q [0:D-1];
    reg [AW-1:0] row_q [0:D-1];
    reg [AW-1:0] first_q [0:D-1];
    board_host #(.M(M), .AW(AW), .FIFO_DEPTH(FIFO_DEPTH), .FIFO_DISTRIBUTED(FIFO_DISTRIBUTED),
                 .BUFFER_DEPTH(BUFFER_DEPTH), .COUNT_AHEAD(COMPARE_LATENCY >= 2 ? 1 : 0), .ID_VALUE(32'hCD7B_0003), .FORMAT_VALUE(FLOAT != 0 ? 0 : WIDTH),
                 .TILE_BOXES_VALUE(TILE_BOXES),
                 .TILE_TIMING_VALUE(TILED ? (TILE_LATENCY & 32'hFFFF) | (32'd1 << 16) : 0)) host (
        .clk(clk), .reset(reset), .addr(addr), .wdata(wdata), .we(we), .re(re), .rdata(rdata), .rvalid(rvalid),
        .irq(irq), .offset(offset), .top_register(32'd0), .store_we(store_we), .store_index(store_index),
        .store_data(store_data), .start_go(start_go), .resume_go(resume_go), .enable(enable), .state(state), .cycles(cycles),
        .stalls(stalls), .object_count(object_count), .done_now(done_now), .sweeping(src_sweeping), .leaving(kind_q[D-1]),
        .lane_hits(lane_hits), .lane_hits_next(lane_hits_next), .pair_row(row_q[D-1]), .pair_first(first_q[D-1]), .pair_columns({(LANES*AW){1'b0}}),
        .pushed_hits(pushed_hits), .out_valid(out_valid), .out_pair(out_pair), .fifo_level(fifo_level),
        .buffered(buffered), .total_pairs(total_pairs));

    // ------------------------------------------------------------------
    // The slot source: address generator (block RAM) or tile walker (SSRAM).
    wire src_window, src_finished;
    wire [AW-1:0] src_row, src_first;
    wire [LANES-1:0] src_valid;
    wire [AW-1:0] port0_addr;               // block RAM: row; tiled: unused
    wire [LANES*AW-1:0] lane_addr;          // block RAM: columns
    wire [TAW-1:0] row_local;
    wire [LANES*TAW-1:0] columns_local;
    wire row_buffer, column_buffer;
    wire [1:0] land_column, land_row;
    wire [TAW-1:0] land_addr;
    wire loader_re;
    wire [AW-1:0] loader_addr;

    generate
        if (!TILED) begin : g_untiled
            address_generator #(.M(M), .AW(AW)) generator (
                .clk(clk), .start(start_go), .enable(enable), .objects(object_count[AW:0]),
                .sweeping(src_sweeping), .row(src_row), .columns(lane_addr), .valid(src_valid));
            assign src_window = src_sweeping;
            assign src_finished = !src_sweeping;
            assign src_first = lane_addr[AW-1:0];
            assign port0_addr = src_row;
            assign row_local = 0;
            assign columns_local = 0;
            assign row_buffer = 0;
            assign column_buffer = 0;
            assign land_column = 0;
            assign land_row = 0;
            assign land_addr = 0;
            assign loader_re = 0;
            assign loader_addr = 0;
        end else begin : g_tiled
            tile_walker #(.M(M), .AW(AW), .T(TILE_BOXES), .TAW(TAW), .LAT(TILE_LATENCY)) walker (
                .clk(clk), .start(start_go), .enable(enable), .objects(object_count[AW:0]),
                .sweeping(src_sweeping), .window(src_window), .finished(src_finished),
                .row(src_row), .first(src_first), .valid(src_valid),
                .row_local(row_local), .columns_local(columns_local),
                .row_buffer(row_buffer), .column_buffer(column_buffer),
                .ssram_re(loader_re), .ssram_addr(loader_addr),
                .land_column(land_column), .land_row(land_row), .land_addr(land_addr));
            assign port0_addr = 0;
            assign lane_addr = 0;
        end
    endgenerate
    assign ssram_we = TILED ? store_we : 6'b0;
    assign ssram_addr = TILED ? (store_we != 0 ? store_index : loader_addr) : {AW{1'b0}};
    assign ssram_re = TILED ? loader_re : 1'b0;
    assign ssram_wdata = store_data;

    // ------------------------------------------------------------------
    // Pipeline bookkeeping: what each slot is, row and first column, delayed
    // D slots to meet the lanes' hits.
    reg [LANES-1:0] valid_q;                // with the block RAM outputs
    reg row_buffer_q, column_buffer_q;
    reg end_issued;
    wire [1:0] issue_kind = src_window ? WINDOW : (src_finished && !end_issued) ? END : BUBBLE;
    integer s;
    always @(posedge clk) begin
        if (start_go) begin
            for (s = 0; s < D; s = s + 1) kind_q[s] <= BUBBLE;
            valid_q <= 0;
            end_issued <= 0;
        end else if (enable) begin
            kind_q[0] <= issue_kind;
            row_q[0] <= src_row;
            first_q[0] <= src_first;
            valid_q <= src_valid;
            row_buffer_q <= row_buffer;
            column_buffer_q <= column_buffer;
            if (src_finished) end_issued <= 1;
            for (s = 1; s < D; s = s + 1) begin
                kind_q[s] <= kind_q[s-1];
                row_q[s] <= row_q[s-1];
                first_q[s] <= first_q[s-1];
            end
        end
    end

    // ------------------------------------------------------------------
    // Coordinate memories and lanes. Port p of a 2m-port memory is copy p/2,
    // side p%2 (A, B); port 0 holds box i, port k+1 feeds lane k. Each copy
    // holds the six coordinates (six block RAMs) and the lanes it feeds sit
    // beside it.
    wire [6*WIDTH-1:0] box_i;
    wire [6*32-1:0] land_words = ssram_rdata;
    genvar p;
    generate
        if (!TILED) begin : g_block_ram
            wire writing = store_we != 0;
            for (p = 0; p < M; p = p + 1) begin : g_copy
                wire [6*WIDTH-1:0] qa, qb;
                wire [AW-1:0] read_a;
                if (p == 0) begin : g_port0
                    assign read_a = port0_addr;
                    assign box_i = qa;
                end else begin : g_port_a
                    assign read_a = lane_addr[(2*p-1)*AW +: AW];
                    compare_lane #(.FLOAT(FLOAT), .WIDTH(WIDTH), .LATENCY(COMPARE_LATENCY)) lane_a (
                        .clk(clk), .enable(enable), .valid_in(valid_q[2*p-1]),
                        .box_i(box_i), .box_j(qa), .hit(lane_hits[2*p-1]), .hit_next(lane_hits_next[2*p-1]));
                end
                coordinate_copy #(.W(WIDTH), .AW(AW)) memory (
                    .clk(clk), .en_a(enable | writing), .we(store_we), .addr_a(writing ? store_index : read_a),
                    .d(store_data), .q_a(qa), .en_b(enable), .addr_b(lane_addr[2*p*AW +: AW]), .q_b(qb));
                compare_lane #(.FLOAT(FLOAT), .WIDTH(WIDTH), .LATENCY(COMPARE_LATENCY)) lane_b (
                    .clk(clk), .enable(enable), .valid_in(valid_q[2*p]),
                    .box_i(box_i), .box_j(qb), .hit(lane_hits[2*p]), .hit_next(lane_hits_next[2*p]));
            end
        end else begin : g_tiles
            // Row buffers (port 0), ping and pong; then the column buffers, ping
            // and pong, m copies each (copy 0's side A only takes the loads).
            wire [6*WIDTH-1:0] row_q0, row_q1, row_unused0, row_unused1;
            coordinate_copy #(.W(WIDTH), .AW(TAW)) row0 (
                .clk(clk), .en_a(enable | land_row[0]), .we({6{land_row[0]}}),
                .addr_a(land_row[0] ? land_addr : row_local), .d(land_words), .q_a(row_q0),
                .en_b(1'b0), .addr_b({TAW{1'b0}}), .q_b(row_unused0));
            coordinate_copy #(.W(WIDTH), .AW(TAW)) row1 (
                .clk(clk), .en_a(enable | land_row[1]), .we({6{land_row[1]}}),
                .addr_a(land_row[1] ? land_addr : row_local), .d(land_words), .q_a(row_q1),
                .en_b(1'b0), .addr_b({TAW{1'b0}}), .q_b(row_unused1));
            assign box_i = row_buffer_q ? row_q1 : row_q0;
            for (p = 0; p < M; p = p + 1) begin : g_copy
                wire [6*WIDTH-1:0] qa0, qb0, qa1, qb1;
                wire [TAW-1:0] read_a;
                if (p == 0) begin : g_load_only
                    assign read_a = {TAW{1'b0}};
                end else begin : g_port_a
                    assign read_a = columns_local[(2*p-1)*TAW +: TAW];
                    compare_lane #(.FLOAT(FLOAT), .WIDTH(WIDTH), .LATENCY(COMPARE_LATENCY)) lane_a (
                        .clk(clk), .enable(enable), .valid_in(valid_q[2*p-1]),
                        .box_i(box_i), .box_j(column_buffer_q ? qa1 : qa0), .hit(lane_hits[2*p-1]), .hit_next(lane_hits_next[2*p-1]));
                end
                coordinate_copy #(.W(WIDTH), .AW(TAW)) ping (
                    .clk(clk), .en_a(enable | land_column[0]), .we({6{land_column[0]}}),
                    .addr_a(land_column[0] ? land_addr : read_a), .d(land_words), .q_a(qa0),
                    .en_b(enable), .addr_b(columns_local[2*p*TAW +: TAW]), .q_b(qb0));
                coordinate_copy #(.W(WIDTH), .AW(TAW)) pong (
                    .clk(clk), .en_a(enable | land_column[1]), .we({6{land_column[1]}}),
                    .addr_a(land_column[1] ? land_addr : read_a), .d(land_words), .q_a(qa1),
                    .en_b(enable), .addr_b(columns_local[2*p*TAW +: TAW]), .q_b(qb1));
                compare_lane #(.FLOAT(FLOAT), .WIDTH(WIDTH), .LATENCY(COMPARE_LATENCY)) lane_b (
                    .clk(clk), .enable(enable), .valid_in(valid_q[2*p]),
                    .box_i(box_i), .box_j(column_buffer_q ? qb1 : qb0), .hit(lane_hits[2*p]), .hit_next(lane_hits_next[2*p]));
            end
        end
    endgenerate

endmodule
