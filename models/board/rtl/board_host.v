// The host side both board tops share (collision_board_top.v, the seed's
// all-pairs board, and grid_board_top.v): the register bus, the coordinate
// windows and the delta stream into the box store, the error causes, the
// pair FIFO, the pair buffer and its window, and the controller. A top adds
// its slot source, memories and lanes: it tells this block which slot
// leaves the compare stages (bubble, window or end marker), the lanes' hits
// and the boxes they pair, and answers reads of its own registers (offsets
// this block leaves at 0). The cycle semantics and where they depart from
// the C++ model are collision_board_top.v's header.
module board_host #(
    parameter M = 2,
    parameter AW = 9,                // 2^AW boxes
    parameter FIFO_DEPTH = 512,
    parameter FIFO_DISTRIBUTED = 0,
    parameter BUFFER_DEPTH = 512,
    parameter LISTED = 0,            // pair_collector's: 1 when each lane's column index is given
    parameter COUNT_AHEAD = 0,       // pair_collector's: 1 when lane_hits_next is what lane_hits becomes
    parameter [31:0] ID_VALUE = 32'hCD7B_0003,
    parameter [31:0] FORMAT_VALUE = 0,        // FORMAT: 0 float32, else the fixed-point width
    parameter [31:0] TILE_BOXES_VALUE = 0,    // TILE_BOXES
    parameter [31:0] TILE_TIMING_VALUE = 0    // TILE_TIMING: SSRAM latency, cycles a box << 16
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
    // the top's registers
    output wire [11:0]       offset,            // the register a read addresses
    input  wire [31:0]       top_register,      // its value, for the top's own offsets (else 0)
    // writes into the box store: six coordinate words of box store_index
    output reg  [5:0]        store_we,
    output reg  [AW-1:0]     store_index,
    output reg  [6*32-1:0]   store_data,
    // control
    output wire              start_go,          // START taken this edge
    output wire              resume_go,
    output wire              enable,            // the pipeline advances this edge (a slot)
    output wire [4:0]        state,             // board_control's one-hot state
    output wire [63:0]       cycles,
    output wire [63:0]       stalls,
    output reg  [31:0]       object_count,
    output wire              done_now,          // the sweep ends at this edge
    input  wire              sweeping,          // the slot source has windows left
    // the slot leaving the compare stages: 0 bubble, 1 window, 2 end marker
    input  wire [1:0]        leaving,
    input  wire [2*M-2:0]    lane_hits,
    input  wire [2*M-2:0]    lane_hits_next,    // at the next edge with enable (COUNT_AHEAD)
    input  wire [AW-1:0]     pair_row,
    input  wire [AW-1:0]     pair_first,        // LISTED = 0: lane k pairs with pair_first + k
    input  wire [(2*M-1)*AW-1:0] pair_columns,  // LISTED = 1: lane k's column at k*AW
    // what the lockstep probes read
    output wire [2*M-2:0]    pushed_hits,
    output wire              out_valid,
    output wire [2*AW-1:0]   out_pair,
    output wire [$clog2(FIFO_DEPTH+1)-1:0] fifo_level,
    output reg  [(BUFFER_DEPTH > 1 ? $clog2(BUFFER_DEPTH) : 1):0] buffered,   // PAIR_COUNT
    output reg  [63:0]       total_pairs
);
    localparam LANES = 2 * M - 1;
    localparam BAW = BUFFER_DEPTH > 1 ? $clog2(BUFFER_DEPTH) : 1;
    localparam [31:0] CAPACITY = 32'd1 << AW;
    localparam [31:0] BOX_BANKS = 1;               // one box bank: no double buffering
    localparam [1:0] END = 2, WINDOW = 1;
    // BoardError causes
    localparam [31:0] E_START_BUSY = 1, E_TOO_MANY = 2, E_RESUME = 3, E_WRITE_BUSY = 4,
                      E_DELTA_INDEX = 6, E_DELTA_INCOMPLETE = 7, E_PAIR_FORMAT = 8, E_PAIR_BANK = 10;

    wire running = state[1] | state[2];
    wire paused = state[3];
    wire done = state[4];
    wire busy = running | paused;
    wire control_irq;       // board_control's own line; the host's interrupt is irq_pending (cleared by ACK)

    // ------------------------------------------------------------------
    // Host writes
    wire [3:0] region = addr[27:24];
    wire reg_access = region == 0 && addr[23:12] == 0;
    assign offset = addr[11:0];
    wire reg_write = we && reg_access;
    wire control_write = reg_write && offset == 12'h004;
    wire cmd_abort = reset || (control_write && wdata[3]);
    wire cmd_start = control_write && !wdata[3] && wdata[0];
    wire cmd_resume = control_write && !wdata[3] && !wdata[0] && wdata[1];
    wire cmd_ack = control_write && wdata[3:0] == 4'b0100;

    reg error;
    reg [31:0] error_cause;
    reg irq_pending;
    reg [2:0] delta_filled;
    reg [31:0] delta_words [0:5];   // the record so far: index, then coordinates
    reg [31:0] delta_records;
    reg end_seen;
    reg pair_bank;                  // PAIR_BANK: 0 current pairs, 1 the previous (none: one bank)

    assign start_go = cmd_start && !busy && object_count <= CAPACITY && delta_filled == 0;
    assign resume_go = cmd_resume && paused;

    // Coordinate and delta writes into the box store.
    wire coordinate_window = region >= 1 && region <= 6;
    wire [2:0] coordinate = region[2:0] - 3'd1;
    wire [21:0] word_index = addr[23:2];
    wire in_capacity = (word_index >> AW) == 0;
    wire coordinate_write = we && coordinate_window && in_capacity;
    wire delta_write = we && region == 9;
    wire delta_complete = delta_write && !busy && delta_filled == 6;
    wire delta_in_range = (delta_words[0] >> AW) == 0;
    // The write reaches the box store a cycle after the bus's: the address
    // decode and the busy check end in registers, not in the memories'
    // address and enable (the whole board's longest path when they did).
    // The store is not read back by the host, and a START on the next bus
    // cycle starts the sweep at that edge, so its first read comes after.
    integer c;
    always @(posedge clk) begin
        store_we <= 0;
        store_index <= word_index[AW-1:0];
        store_data <= {6{wdata}};
        if (coordinate_write && !busy) store_we[coordinate] <= 1'b1;
        if (delta_complete && delta_in_range) begin
            store_we <= 6'b111111;
            store_index <= delta_words[0][AW-1:0];
            for (c = 0; c < 5; c = c + 1) store_data[c*32 +: 32] <= delta_words[c + 1];
        end
        if (reset) store_we <= 0;
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
    // Pair FIFO and pair buffer.
    reg [BAW-1:0] buffer_write_at;
    localparam [BAW:0] BUFFER_FULL = BUFFER_DEPTH[BAW:0];
    // Full kept beside the count, so the pause (and with it the pipeline's
    // enable) waits on no compare.
    reg buffer_full;
    wire room;
    wire drain_ready = running && !buffer_full;
    wire pause_now = running && fifo_level != 0 && buffer_full;
    wire flow = running && !end_seen && !pause_now;
    wire push = flow && leaving == WINDOW;
    localparam PCW = $clog2(2 * M);
    wire [PCW-1:0] pushed_count;  // pairs in pushed_hits (the FIFO counts them)
    assign pushed_hits = push ? lane_hits : {LANES{1'b0}};
    wire take = fifo_level != 0 && drain_ready;
    wire fifo_empties = fifo_level == 0 || (fifo_level == 1 && take);
    assign done_now = running && !pause_now && (end_seen || (enable && leaving == END)) && fifo_empties;
    pair_collector #(.M(M), .AW(AW), .DEPTH(FIFO_DEPTH), .DISTRIBUTED(FIFO_DISTRIBUTED), .DRAIN_FIRST(1),
                     .LISTED(LISTED), .COUNT_AHEAD(COUNT_AHEAD)) collector (
        .clk(clk), .clear(start_go), .hits(pushed_hits), .hits_next(lane_hits_next), .hits_step(enable),
        .push(push), .pushed(pushed_count), .row(pair_row), .first(pair_first), .columns(pair_columns),
        .drain_ready(drain_ready), .room(room), .out_valid(out_valid), .out_pair(out_pair), .level(fifo_level));

    board_control #(.CW(64), .MODEL_TIMING(1)) control (
        .clk(clk), .abort(cmd_abort), .start(start_go), .resume(resume_go), .sweeping(sweeping),
        .pipeline_empty(done_now), .fifo_room(room && !end_seen), .buffer_full(pause_now),
        .enable(enable), .state(state), .cycles(cycles), .stalls(stalls), .irq(control_irq));

    // Host reads of the pair buffer: pair k at 8k, first index in the low word.
    wire pair_read = re && region == 7;
    wire [2*AW-1:0] pair_word;
    board_sdp_ram #(.W(2 * AW), .DEPTH(BUFFER_DEPTH), .AW(BAW)) pair_buffer (
        .clk(clk), .we(out_valid), .waddr(buffer_write_at), .d(out_pair),
        .re(pair_read), .raddr(addr[BAW+2:3]), .q(pair_word));

    always @(posedge clk) begin
        if (reset) begin
            buffered <= 0;
            buffer_full <= 0;
            total_pairs <= 0;
        end
        if (cmd_abort) begin
            end_seen <= 0;
        end else if (start_go) begin
            end_seen <= 0;
            buffered <= 0;
            buffer_write_at <= 0;
            total_pairs <= 0;
            buffer_full <= 0;
        end else begin
            if (enable && leaving == END) end_seen <= 1;
            if (resume_go) begin
                buffered <= 0;
                buffer_full <= 0;
            end else if (take) begin
                buffered <= buffered + 1'b1;
                buffer_full <= buffered == BUFFER_FULL - 1'b1;
            end
            if (resume_go) buffer_write_at <= 0;
            else if (out_valid) buffer_write_at <= buffer_write_at + 1'b1;
            if (enable) total_pairs <= total_pairs + {{(63-PCW){1'b0}}, pushed_count};
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
            12'h03C: register_value = FORMAT_VALUE;
            12'h040: register_value = TILE_BOXES_VALUE;
            12'h044: register_value = TILE_TIMING_VALUE;
            12'h048: register_value = 0;
            12'h04C: register_value = pair_bank ? 0 : {{(30-BAW){1'b0}}, buffered, 1'b0};
            12'h050: register_value = delta_records;
            12'h054: register_value = BOX_BANKS;
            12'h058: register_value = 0;                        // HOST_BANK: the one bank
            12'h05C: register_value = {31'b0, pair_bank};
            default: register_value = top_register;
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
