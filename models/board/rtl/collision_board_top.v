// The whole collision board: host register bus, six coordinate memories,
// the address generator (or, on a tiled board, the tile walker and loader
// with the boxes in six SSRAM banks), 2m-1 compare lanes, the pair FIFO,
// the pair buffer and the controller. It follows the C++ BoardCore with the
// clocked engine (models/board/board_core.*, models/clocked_engine/) edge
// for edge: the same pairs in the same order, the same CYCLES, STALLS,
// TOTAL_PAIRS, PAIR_COUNT, STATUS and ERROR_CAUSE (tests/rtl checks it).
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
    localparam [31:0] CAPACITY = 32'd1 << AW;
    localparam [31:0] ID_VALUE = 32'hCD7B_0003;   // register map version 3
    localparam [31:0] BOX_BANKS = 1;               // one box bank: no double buffering
    localparam [1:0] BUBBLE = 0, WINDOW = 1, END = 2;
    // BoardError causes
    localparam [31:0] E_START_BUSY = 1, E_TOO_MANY = 2, E_RESUME = 3, E_WRITE_BUSY = 4,
                      E_DELTA_INDEX = 6, E_DELTA_INCOMPLETE = 7, E_PAIR_FORMAT = 8, E_PAIR_BANK = 10;

    // ------------------------------------------------------------------
    // Controller
    wire [4:0] state;
    wire [63:0] cycles, stalls;
    wire running = state[1] | state[2];
    wire paused = state[3];
    wire done = state[4];
    wire busy = running | paused;
    wire enable;            // the pipeline advances this edge (a slot)
    wire control_irq;       // board_control's own line; the host's interrupt is irq_pending (cleared by ACK)

    // ------------------------------------------------------------------
    // Host writes
    wire [3:0] region = addr[27:24];
    wire reg_access = region == 0 && addr[23:12] == 0;
    wire [11:0] offset = addr[11:0];
    wire reg_write = we && reg_access;
    wire control_write = reg_write && offset == 12'h004;
    wire cmd_abort = reset || (control_write && wdata[3]);
    wire cmd_start = control_write && !wdata[3] && wdata[0];
    wire cmd_resume = control_write && !wdata[3] && !wdata[0] && wdata[1];
    wire cmd_ack = control_write && wdata[3:0] == 4'b0100;

    reg [31:0] object_count;
    reg error;
    reg [31:0] error_cause;
    reg irq_pending;
    reg [2:0] delta_filled;
    reg [31:0] delta_words [0:5];   // the record so far: index, then coordinates
    reg [31:0] delta_records;
    reg end_seen;
    reg pair_bank;                  // PAIR_BANK: 0 current pairs, 1 the previous (none: one bank)

    wire start_go = cmd_start && !busy && object_count <= CAPACITY && delta_filled == 0;
    wire resume_go = cmd_resume && paused;

    // Coordinate and delta writes; 'store' writes reach block RAM, or SSRAM when tiled.
    wire coordinate_window = region >= 1 && region <= 6;
    wire [2:0] coordinate = region[2:0] - 3'd1;
    wire [21:0] word_index = addr[23:2];
    wire in_capacity = (word_index >> AW) == 0;
    wire coordinate_write = we && coordinate_window && in_capacity;
    wire delta_write = we && region == 9;
    wire delta_complete = delta_write && !busy && delta_filled == 6;
    wire delta_in_range = (delta_words[0] >> AW) == 0;
    reg  [5:0]       store_we;
    reg  [AW-1:0]    store_index;
    reg  [6*32-1:0]  store_data;
    integer c;
    always @* begin
        store_we = 0;
        store_index = word_index[AW-1:0];
        store_data = {6{wdata}};
        if (coordinate_write && !busy) store_we[coordinate] = 1'b1;
        if (delta_complete && delta_in_range) begin
            store_we = 6'b111111;
            store_index = delta_words[0][AW-1:0];
            for (c = 0; c < 5; c = c + 1) store_data[c*32 +: 32] = delta_words[c + 1];
        end
    end

    // Error causes, as BoardCore raises them (the last one written wins).
    reg raise;
    reg [31:0] cause;
    always @* begin
        raise = 0;
        cause = 0;
        if (cmd_start && busy) begin raise = 1; cause = E_START_BUSY; end
        else if (cmd_start && object_count > CAPACITY) begin raise = 1; cause = E_TOO_MANY; end
        else if (cmd_start && delta_filled != 0) begin raise = 1; cause = E_DELTA_INCOMPLETE; end
        if (cmd_resume && !paused) begin raise = 1; cause = E_RESUME; end
        if (reg_write && offset == 12'h00C && busy) begin raise = 1; cause = E_WRITE_BUSY; end
        if (reg_write && offset == 12'h048) begin
            if (busy) begin raise = 1; cause = E_WRITE_BUSY; end
            else if (wdata != 0) begin raise = 1; cause = E_PAIR_FORMAT; end
        end
        if (reg_write && offset == 12'h05C && wdata > 1) begin raise = 1; cause = E_PAIR_BANK; end
        if ((coordinate_write || delta_write) && busy) begin raise = 1; cause = E_WRITE_BUSY; end
        if (delta_complete && !delta_in_range) begin raise = 1; cause = E_DELTA_INDEX; end
    end

    // ------------------------------------------------------------------
    // The slot source: address generator (block RAM) or tile walker (SSRAM).
    wire src_sweeping, src_window, src_finished;
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
    reg [1:0] kind_q [0:D-1];
    reg [AW-1:0] row_q [0:D-1];
    reg [AW-1:0] first_q [0:D-1];
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
    wire [LANES-1:0] lane_hits;
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
                        .box_i(box_i), .box_j(qa), .hit(lane_hits[2*p-1]));
                end
                coordinate_copy #(.W(WIDTH), .AW(AW)) memory (
                    .clk(clk), .en_a(enable | writing), .we(store_we), .addr_a(writing ? store_index : read_a),
                    .d(store_data), .q_a(qa), .en_b(enable), .addr_b(lane_addr[2*p*AW +: AW]), .q_b(qb));
                compare_lane #(.FLOAT(FLOAT), .WIDTH(WIDTH), .LATENCY(COMPARE_LATENCY)) lane_b (
                    .clk(clk), .enable(enable), .valid_in(valid_q[2*p]),
                    .box_i(box_i), .box_j(qb), .hit(lane_hits[2*p]));
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
                        .box_i(box_i), .box_j(column_buffer_q ? qa1 : qa0), .hit(lane_hits[2*p-1]));
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
                    .box_i(box_i), .box_j(column_buffer_q ? qb1 : qb0), .hit(lane_hits[2*p]));
            end
        end
    endgenerate

    // ------------------------------------------------------------------
    // Pair FIFO and pair buffer.
    localparam FW = $clog2(FIFO_DEPTH + 1);
    wire [1:0] leaving = kind_q[D-1];
    reg [BAW:0] buffered;                   // PAIR_COUNT
    reg [BAW-1:0] buffer_write_at;
    reg [63:0] total_pairs;
    localparam [BAW:0] BUFFER_FULL = BUFFER_DEPTH[BAW:0];
    wire buffer_full = buffered == BUFFER_FULL;
    wire [FW-1:0] fifo_level;
    wire room;
    wire drain_ready = running && !buffer_full;
    wire pause_now = running && fifo_level != 0 && buffer_full;
    wire flow = running && !end_seen && !pause_now;
    wire [LANES-1:0] pushed_hits = flow && leaving == WINDOW ? lane_hits : {LANES{1'b0}};
    wire take = fifo_level != 0 && drain_ready;
    wire fifo_empties = fifo_level == 0 || (fifo_level == 1 && take);
    wire done_now = running && !pause_now && (end_seen || (enable && leaving == END)) && fifo_empties;
    wire out_valid;
    wire [2*AW-1:0] out_pair;
    pair_collector #(.M(M), .AW(AW), .DEPTH(FIFO_DEPTH), .DISTRIBUTED(FIFO_DISTRIBUTED), .DRAIN_FIRST(1)) collector (
        .clk(clk), .clear(start_go), .hits(pushed_hits), .row(row_q[D-1]), .first(first_q[D-1]),
        .drain_ready(drain_ready), .room(room), .out_valid(out_valid), .out_pair(out_pair), .level(fifo_level));

    board_control #(.CW(64), .MODEL_TIMING(1)) control (
        .clk(clk), .abort(cmd_abort), .start(start_go), .resume(resume_go), .sweeping(src_sweeping),
        .pipeline_empty(done_now), .fifo_room(room && !end_seen), .buffer_full(pause_now),
        .enable(enable), .state(state), .cycles(cycles), .stalls(stalls), .irq(control_irq));

    reg [LANES:0] pushed_count;
    integer h;
    always @* begin
        pushed_count = 0;
        for (h = 0; h < LANES; h = h + 1) pushed_count = pushed_count + {{LANES{1'b0}}, pushed_hits[h]};
    end

    // Host reads of the pair buffer: pair k at 8k, first index in the low word.
    wire pair_read = re && region == 7;
    wire [2*AW-1:0] pair_word;
    board_sdp_ram #(.W(2 * AW), .DEPTH(BUFFER_DEPTH), .AW(BAW)) pair_buffer (
        .clk(clk), .we(out_valid), .waddr(buffer_write_at), .d(out_pair),
        .re(pair_read), .raddr(addr[BAW+2:3]), .q(pair_word));

    always @(posedge clk) begin
        if (reset) begin
            buffered <= 0;
            total_pairs <= 0;
        end
        if (cmd_abort) begin
            end_seen <= 0;
        end else if (start_go) begin
            end_seen <= 0;
            buffered <= 0;
            buffer_write_at <= 0;
            total_pairs <= 0;
        end else begin
            if (enable && leaving == END) end_seen <= 1;
            if (resume_go) buffered <= 0;
            else if (take) buffered <= buffered + 1'b1;
            if (resume_go) buffer_write_at <= 0;
            else if (out_valid) buffer_write_at <= buffer_write_at + 1'b1;
            if (enable) total_pairs <= total_pairs + {{(63-LANES){1'b0}}, pushed_count};
        end
    end

    // ------------------------------------------------------------------
    // Registers
    always @(posedge clk) begin
        if (reset) begin
            object_count <= 0;
            delta_records <= 0;
            pair_bank <= 0;
        end else if (reg_write && offset == 12'h05C && wdata <= 1) begin
            pair_bank <= wdata[0];      // accepted while busy too, as the model's
        end
        if (cmd_abort) begin
            error <= 0;
            error_cause <= 0;
            irq_pending <= 0;
            delta_filled <= 0;
        end else begin
            if (reg_write && offset == 12'h00C && !busy) object_count <= wdata;
            if (start_go) begin
                error <= 0;
                error_cause <= 0;
                irq_pending <= 0;
                delta_records <= 0;
            end else if (resume_go || cmd_ack) begin
                irq_pending <= 0;
            end
            if (running && (pause_now || done_now)) irq_pending <= 1;
            if (raise) begin
                error <= 1;
                error_cause <= cause;
                irq_pending <= 1;
            end
            if (delta_write && !busy) begin
                if (delta_filled == 6) begin
                    delta_filled <= 0;
                    if (delta_in_range) delta_records <= delta_records + 1;
                end else begin
                    delta_words[delta_filled] <= wdata;
                    delta_filled <= delta_filled + 1'b1;
                end
            end
        end
    end
    assign irq = irq_pending;

    // Reads: one cycle later.
    reg [31:0] register_value;
    always @* begin
        case (offset)
            12'h000: register_value = ID_VALUE;
            12'h008: register_value = {27'b0, irq_pending, error, paused, done, busy};
            12'h00C: register_value = object_count;
            12'h010: register_value = pair_bank ? 0 : {{(31-BAW){1'b0}}, buffered};
            12'h014: register_value = cycles[31:0];
            12'h018: register_value = cycles[63:32];
            12'h01C: register_value = stalls[31:0];
            12'h020: register_value = stalls[63:32];
            12'h024: register_value = total_pairs[31:0];
            12'h028: register_value = total_pairs[63:32];
            12'h02C: register_value = M;
            12'h030: register_value = CAPACITY;
            12'h034: register_value = BUFFER_DEPTH;
            12'h038: register_value = error_cause;
            12'h03C: register_value = FLOAT != 0 ? 0 : WIDTH;
            12'h040: register_value = TILE_BOXES;
            12'h044: register_value = TILED ? (TILE_LATENCY & 32'hFFFF) | (32'd1 << 16) : 0;
            12'h048: register_value = 0;
            12'h04C: register_value = pair_bank ? 0 : {{(30-BAW){1'b0}}, buffered, 1'b0};
            12'h050: register_value = delta_records;
            12'h054: register_value = BOX_BANKS;
            12'h058: register_value = 0;                        // HOST_BANK: the one bank
            12'h05C: register_value = {31'b0, pair_bank};
            default: register_value = 0;
        endcase
    end
    reg read_pair, read_high, read_previous;
    reg [31:0] register_q;
    always @(posedge clk) begin
        rvalid <= re;
        read_pair <= pair_read;
        read_high <= addr[2];
        read_previous <= pair_bank;
        register_q <= re && reg_access ? register_value : 0;
    end
    always @* begin
        if (read_pair && read_previous) rdata = 0;   // the previous pair buffer: empty
        else if (read_pair) rdata = {{(32-AW){1'b0}}, read_high ? pair_word[AW-1:0] : pair_word[2*AW-1 -: AW]};  // {row, column}
        else rdata = register_q;
    end
endmodule
