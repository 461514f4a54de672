// The tile walker as first written (models/board/rtl/tile_walker.v before it
// was rebuilt for the clock), kept as the reference the rebuilt walker is held
// to slot for slot by tb_tile_walker.v: its schedule is the model's, checked
// against BoardCore by the whole-board equivalence tests.
module tile_walker_reference #(
    parameter M = 2,
    parameter AW = 10,      // SSRAM depth 2^AW boxes
    parameter T = 64,       // boxes a tile
    parameter TAW = 6,      // tile buffer address bits: 2^TAW >= T
    parameter LAT = 2       // SSRAM read latency in cycles
) (
    input  wire                    clk,
    input  wire                    start,
    input  wire                    enable,     // a slot: the pipeline advances
    input  wire [AW:0]             objects,
    output wire                    sweeping,   // blocks are left
    output wire                    window,     // this slot issues addresses
    output wire                    finished,   // no window is left: the end marker's slot
    output wire [AW-1:0]           row,        // global indices for the pairs
    output wire [AW-1:0]           first,
    output wire [2*M-2:0]          valid,
    output wire [TAW-1:0]          row_local,  // port 0's address in the row buffer
    output wire [(2*M-1)*TAW-1:0]  columns_local,
    output wire                    row_buffer,    // row buffer read this slot
    output wire                    column_buffer, // column buffer read this slot
    // SSRAM reads (the banks share the address) and where their words land
    output wire                    ssram_re,
    output wire [AW-1:0]           ssram_addr,
    output wire [1:0]              land_column,   // write column buffer 0 / 1
    output wire [1:0]              land_row,      // write row buffer 0 / 1
    output wire [TAW-1:0]          land_addr
);
    localparam LANES = 2 * M - 1;

    // ---- the walker ----
    reg [AW:0] n, a_base, b_base, r_reg, c_reg;
    reg a_par, b_par, k_par, in_block, ended, loaded;
    // ---- the loader ----
    reg         reading;        // reads left to issue
    reg [AW:0]  load_first;     // the loaded tile's first box
    reg [AW:0]  load_n;         // its boxes
    reg [AW:0]  load_j;         // reads issued
    reg [AW+7:0] load_cnt;      // slots since the load began
    reg         load_active;    // begun and not yet readable
    reg         load_col_par, load_row_par, load_with_row;

    wire [AW+1:0] a_next = a_base + T;
    wire [AW+1:0] b_next = b_base + T;
    wire [AW:0] row_end = a_next > n ? n : a_next[AW:0];
    wire [AW:0] col_end = b_next > n ? n : b_next[AW:0];
    wire diag = a_base == b_base;
    wire last_block = a_next >= n;

    // Land: the current load becomes readable in this slot.
    wire lands = load_active && load_cnt == load_n + LAT;
    wire ready = loaded | lands;

    wire entering = !ended && !in_block && ready;
    wire [AW:0] r = entering ? a_base : r_reg;
    wire [AW:0] c = entering ? (diag ? a_base + 1'b1 : b_base) : c_reg;
    wire nonempty = r < row_end && c < col_end;   // false only entering a one-box last tile
    assign window = !ended && (in_block || entering) && nonempty;
    assign finished = ended || (entering && !nonempty);
    assign sweeping = !ended;

    // The window's successor and the block's end.
    wire [AW+1:0] c_step = c + LANES;
    wire row_done = c_step >= col_end;
    wire [AW:0] r_after = row_done ? r + 1'b1 : r;
    wire [AW+1:0] c_after = row_done ? (diag ? r + 2'd2 : b_base) : c_step;
    wire block_done = r_after >= row_end || c_after >= col_end;

    assign row = r[AW-1:0];
    assign first = c[AW-1:0];
    wire [AW:0] r_off = r - a_base;
    assign row_local = r_off[TAW-1:0];
    assign row_buffer = a_par;
    assign column_buffer = k_par;
    genvar k;
    generate
        for (k = 0; k < LANES; k = k + 1) begin : g_port
            wire [AW+1:0] j = c + k;
            wire [AW+1:0] j_off = j - b_base;
            assign columns_local[k*TAW +: TAW] = j_off[TAW-1:0];
            assign valid[k] = window && j < col_end;
        end
    endgenerate

    // The next block's load begins in the slot its predecessor is entered.
    wire begin_next = enable && entering && !last_block;
    wire same_row = b_next < n;                          // the next block is (a, b+1)
    wire [AW:0] next_col = same_row ? b_next[AW:0] : a_next[AW:0];
    wire next_col_par = same_row ? ~b_par : ~a_par;
    wire [AW+1:0] next_col_end_raw = next_col + T;
    wire [AW:0] next_n = (next_col_end_raw > n ? n : next_col_end_raw[AW:0]) - next_col;
    // Reads of this slot: box 0 of a load begun now, else the load under way.
    wire read_now = enable && (begin_next || reading);
    wire [AW:0] read_box = begin_next ? next_col : load_first + load_j;
    wire [AW:0] read_j = begin_next ? 0 : load_j;
    wire read_col_par = begin_next ? ~k_par : load_col_par;
    wire read_row_par = begin_next ? next_col_par : load_row_par;
    wire read_with_row = begin_next ? diag && same_row : load_with_row;
    assign ssram_re = read_now;
    assign ssram_addr = read_box[AW-1:0];

    always @(posedge clk) begin
        if (start) begin
            n <= objects;
            a_base <= 0;
            b_base <= 0;
            a_par <= 0;
            b_par <= 0;
            k_par <= 0;
            in_block <= 0;
            ended <= objects < 2;
            loaded <= 0;
            // Block 0's tile (rows and columns) loads from the first slot on.
            reading <= objects >= 2;
            load_active <= objects >= 2;
            load_first <= 0;
            load_n <= objects > T ? T : objects;
            load_j <= 0;
            load_cnt <= 0;
            load_col_par <= 0;
            load_row_par <= 0;
            load_with_row <= 1;
        end else if (enable) begin
            // loader
            if (lands) begin
                loaded <= 1;
                load_active <= 0;
            end
            if (begin_next) begin
                loaded <= 0;
                load_active <= 1;
                load_first <= next_col;
                load_n <= next_n;
                load_j <= 1;
                load_cnt <= 1;
                reading <= next_n > 1;
                load_col_par <= ~k_par;
                load_row_par <= next_col_par;
                load_with_row <= diag && same_row;
            end else begin
                load_cnt <= load_cnt + 1;
                if (reading) begin
                    load_j <= load_j + 1;
                    reading <= load_j + 1 < load_n;
                end
            end
            // walker
            if (entering) in_block <= 1;
            if (finished) ended <= 1;
            if (window) begin
                if (block_done) begin
                    in_block <= 0;
                    k_par <= ~k_par;
                    if (same_row) begin
                        b_base <= b_next[AW:0];
                        b_par <= ~b_par;
                    end else begin
                        a_base <= a_next[AW:0];
                        b_base <= a_next[AW:0];
                        a_par <= ~a_par;
                        b_par <= ~a_par;
                        ended <= last_block;
                    end
                end else begin
                    r_reg <= r_after;
                    c_reg <= c_after[AW:0];
                end
            end
        end
    end

    // The SSRAM's words arrive LAT clocks after their read: stage 0 is this
    // cycle's read, stage s the read s cycles ago.
    localparam LW = TAW + 4;  // valid, column buffer, row buffer, with row, address
    wire [LW-1:0] land_now = {read_now, read_col_par, read_row_par, read_with_row, read_j[TAW-1:0]};
    wire [LW-1:0] landing;
    generate
        if (LAT == 0) begin : g_now
            assign landing = land_now;
        end else begin : g_delayed
            reg [LW-1:0] land_q [1:LAT];
            integer s;
            always @(posedge clk) begin
                land_q[1] <= start ? {LW{1'b0}} : land_now;
                for (s = 2; s <= LAT; s = s + 1) land_q[s] <= start ? {LW{1'b0}} : land_q[s-1];
            end
            assign landing = land_q[LAT];
        end
    endgenerate
    wire land_valid = landing[LW-1];
    assign land_column = land_valid ? (landing[LW-2] ? 2'b10 : 2'b01) : 2'b00;
    assign land_row = land_valid && landing[LW-4] ? (landing[LW-3] ? 2'b10 : 2'b01) : 2'b00;
    assign land_addr = landing[TAW-1:0];
endmodule
