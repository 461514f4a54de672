// The tiled board's address generator and tile loader (the C++ model's
// ScheduleWalker and TileLoader, models/address_generator/sweep_schedule.h
// and models/tile_loader/): boxes live in six SSRAM banks (one a coordinate,
// so a box is read in one cycle: cycles_per_box = 1) and are swept in tiles
// of T boxes through double-buffered tile buffers. Blocks run (0,0), (0,1)
// .. (0,nt-1), (1,1) .. (nt-1,nt-1); a diagonal block is the triangular
// sweep of its tile, an off-diagonal block (a,b) puts port 0 on each row of
// tile a and ports 1..2m-1 on all of tile b. Block k's column tile sits in
// column buffer k % 2 and row tile a in row buffer a % 2; block k+1's
// column tile (and, for a block (a,a+1), the same words into the row buffer
// of tile a+1) loads while block k is compared.
//
// Everything moves in slots: clock edges at which the pipeline advances
// (enable), as the model's loader is clocked in address-generator slots. A
// load begun in slot s reads box j in slot s+j and is readable from slot
// s+n+LAT (n boxes, LAT the SSRAM's latency in slots, as the model counts
// it). The SSRAM itself answers LAT clocks after a read, which is never
// later than LAT slots, so its words are written into the tile buffers as
// they arrive while readiness is counted in slots: what the pipeline sees
// is the model's.
//
// Built for the clock: no slot's decision waits on an add. The window's
// place is kept in registers four ways (global row and column, offsets in
// the tiles, columns and rows left), so a row's end, a block's end and each
// lane's valid are compares of a register with a constant. The block after
// the current one (queued) is kept ahead with what is left of the boxes
// past its tiles, so entering it loads registers worked out from registers.
// A load's end travels down a LAT+1-slot pipe instead of a count compared
// with a sum.
module tile_walker #(
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
    localparam NW = AW + 2;         // boxes left past a base: signed, negative past the last tile
    localparam CW = (TAW > $clog2(2 * M) ? TAW : $clog2(2 * M)) + 1;  // counts within a tile: 0 .. T, and LANES
    localparam [NW-1:0] TN = T;
    localparam [CW-1:0] TC = T;
    localparam [CW-1:0] LC = LANES;

    // ---- the current block (a, b): fixed while it is swept ----
    reg [AW:0]   b_base;
    reg [CW-1:0] cols;              // boxes of tile b
    reg diag, last_block, same_row, empty, a_par, k_par;
    // ---- the window's place ----
    reg [AW:0]   r_reg, c_reg;      // row, first column
    reg [CW-1:0] r_off, c_off;      // the same in the tiles
    reg [CW-1:0] rows_left;         // row_end - row
    reg [CW-1:0] left;              // col_end - first column
    reg in_block, ended;
    // ---- the queued block (qa, qb), the one after the current ----
    reg [AW:0]   qa, qb;
    reg [NW-1:0] q_left_a, q_left_b;  // objects - qa, objects - qb
    reg q_diag, q_apar, q_bpar;
    // ---- the loader ----
    reg          loaded, load_active, reading;
    reg [AW:0]   load_addr;         // the next box read
    reg [TAW-1:0] load_j;           // its place in the tile
    reg [CW-1:0] reads_left;        // reads left, this slot's included
    reg          load_col_par, load_row_par, load_with_row;
    reg [LAT:0]  land_pipe;         // the last read, travelling to its slot of readiness

    // Land: the current load becomes readable in this slot.
    wire lands = load_active && land_pipe[LAT];
    wire ready = loaded | lands;

    wire entering = !ended && !in_block && ready;
    assign window = !ended && (in_block || (entering && !empty));
    // A diagonal block of one box has no pair: the last one ends the sweep, another
    // (tiles of one box) is left in the slot it is entered, as the model's walker does.
    assign finished = ended || (entering && empty && last_block);
    wire skip = entering && empty && !last_block;
    assign sweeping = !ended;

    // The window's successor and the block's end.
    wire row_done = left <= LC;
    wire block_done = row_done && rows_left <= (diag ? 2 : 1);
    wire leave = (window && block_done) || skip;

    assign row = r_reg[AW-1:0];
    assign first = c_reg[AW-1:0];
    assign row_local = r_off[TAW-1:0];
    assign row_buffer = a_par;
    assign column_buffer = k_par;
    genvar k;
    generate
        for (k = 0; k < LANES; k = k + 1) begin : g_port
            wire [CW-1:0] j_off = c_off + k;
            assign columns_local[k*TAW +: TAW] = j_off[TAW-1:0];
            assign valid[k] = window && left > k;
        end
    endgenerate

    // The queued block, worked out ahead: its tiles' boxes and where it sits.
    wire [CW-1:0] q_rows = q_left_a >= TN ? TC : q_left_a[CW-1:0];
    wire [CW-1:0] q_cols = q_left_b >= TN ? TC : q_left_b[CW-1:0];
    wire q_same_row = $signed(q_left_b) > $signed(TN);        // the block after it is (qa, qb+1)
    wire q_last = $signed(q_left_a) <= $signed(TN);
    wire q_one_column = q_left_b == 1 || T == 1;

    // The next block's load (its column tile qb) begins in the slot the current block is entered.
    wire begin_next = enable && entering && !last_block;
    wire read_now = enable && (begin_next || reading);
    wire last_read = read_now && (begin_next ? q_one_column : reads_left == 1);
    assign ssram_re = read_now;
    assign ssram_addr = begin_next ? qb[AW-1:0] : load_addr[AW-1:0];
    wire [TAW-1:0] read_j = begin_next ? {TAW{1'b0}} : load_j;
    wire read_col_par = begin_next ? ~k_par : load_col_par;
    wire read_row_par = begin_next ? q_bpar : load_row_par;
    wire read_with_row = begin_next ? diag && same_row : load_with_row;

    wire [CW-1:0] start_rows = objects > T ? TC : objects[CW-1:0];

    always @(posedge clk) begin
        if (start) begin
            // Block (0,0), tile 0 loading into column buffer 0 and row buffer 0; (0,1) queued.
            b_base <= 0;
            cols <= start_rows;
            diag <= 1;
            last_block <= objects <= T;
            same_row <= objects > T;
            empty <= objects < 2 || T == 1;
            a_par <= 0;
            k_par <= 0;
            r_reg <= 0;
            c_reg <= 1;
            r_off <= 0;
            c_off <= 1;
            rows_left <= start_rows;
            left <= start_rows - 1'b1;
            in_block <= 0;
            ended <= objects < 2;
            qa <= 0;
            qb <= T;
            q_left_a <= {1'b0, objects};
            q_left_b <= {1'b0, objects} - TN;
            q_diag <= 0;
            q_apar <= 0;
            q_bpar <= 1;
            loaded <= 0;
            load_active <= objects >= 2;
            reading <= objects >= 2;
            load_addr <= 0;
            load_j <= 0;
            reads_left <= start_rows;
            load_col_par <= 0;
            load_row_par <= 0;
            load_with_row <= 1;
            land_pipe <= 0;
        end else if (enable) begin
            // loader
            land_pipe <= (land_pipe << 1) | last_read;
            if (lands) begin
                loaded <= 1;
                load_active <= 0;
            end
            if (begin_next) begin
                loaded <= 0;
                load_active <= 1;
                load_addr <= qb + 1'b1;
                load_j <= 1;
                reads_left <= q_cols - 1'b1;
                reading <= !q_one_column;
                load_col_par <= ~k_par;
                load_row_par <= q_bpar;
                load_with_row <= diag && same_row;
            end else if (reading) begin
                load_addr <= load_addr + 1'b1;
                load_j <= load_j + 1'b1;
                reads_left <= reads_left - 1'b1;
                reading <= reads_left != 1;
            end
            // walker
            if (entering && !empty) in_block <= 1;
            if (finished) ended <= 1;
            if (leave || window) begin
                if (leave) begin
                    // Enter the queued block's registers; queue the one after it.
                    in_block <= 0;
                    k_par <= ~k_par;
                    ended <= last_block;
                    b_base <= qb;
                    cols <= q_cols;
                    diag <= q_diag;
                    last_block <= q_last;
                    same_row <= q_same_row;
                    empty <= q_diag && (q_left_a == 1 || T == 1);
                    a_par <= q_apar;
                    r_reg <= qa;
                    c_reg <= q_diag ? qa + 1'b1 : qb;
                    r_off <= 0;
                    c_off <= {{CW-1{1'b0}}, q_diag};
                    rows_left <= q_rows;
                    left <= q_cols - q_diag;
                    if (q_same_row) begin
                        qb <= qb + T;
                        q_left_b <= q_left_b - TN;
                        q_diag <= 0;
                        q_bpar <= ~q_bpar;
                    end else begin
                        qa <= qa + T;
                        qb <= qa + T;
                        q_left_a <= q_left_a - TN;
                        q_left_b <= q_left_a - TN;
                        q_diag <= 1;
                        q_apar <= ~q_apar;
                        q_bpar <= ~q_apar;
                    end
                end else if (row_done) begin
                    // The next row: a diagonal block's starts past the diagonal.
                    r_reg <= r_reg + 1'b1;
                    r_off <= r_off + 1'b1;
                    rows_left <= rows_left - 1'b1;
                    c_reg <= diag ? r_reg + 2'd2 : b_base;
                    c_off <= diag ? r_off + 2'd2 : {CW{1'b0}};
                    left <= diag ? rows_left - 2'd2 : cols;
                end else begin
                    c_reg <= c_reg + LANES;
                    c_off <= c_off + LC;
                    left <= left - LC;
                end
            end
        end
    end

    // The SSRAM's words arrive LAT clocks after their read: stage 0 is this
    // cycle's read, stage s the read s cycles ago.
    localparam LW = TAW + 4;  // valid, column buffer, row buffer, with row, address
    wire [LW-1:0] land_now = {read_now, read_col_par, read_row_par, read_with_row, read_j};
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
