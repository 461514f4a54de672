// The grid board's binning sequencer (the C++ GridClockedEngine's issue(),
// models/grid_clocked_engine/grid_clocked_engine.cpp; docs/grid_board.md):
// it walks the passes slot by slot, as the model does, and keeps the cell
// memory they build.
//   bounds  box i read in slot i, its centres taken in slot i + LAT
//   setup   16 slots: the grid's dims (a binary search on 16 g^3 <= N), each
//           axis's extent and scale (one adder and one divider, an axis a slot)
//   count   boxes read ahead through six cell-function units into a FIFO;
//           box i classified in its first slot, held max(1, k) slots,
//           counted in all its cells or none in its last
//   scan    a cell a slot: its count becomes its first entry, busy cells listed
//   place   each binned box's index written at its cells' next entries
//   cells   the busy cells' triangles, the next cell loaded (cell_loader)
//           into the idle half while one is swept
//   large   each tile of large boxes loaded, then every box streamed past it
//           (read ahead from the box store into the row register)
// Slots are clock edges with enable; a stall holds everything. One box a
// slot from the box store (six SSRAM banks, GridSlots::cycles_per_box = 1),
// as the cell loader reads it.
//
// The cell memory (count table, entry lists, busy-cell and large-box lists,
// each box's kind) is grid_cell_memory (models/cell_memory/rtl): register
// files whose box ports read and write all of a box's cells (up to SPAN) in
// its last count or place slot, where the model's board spends max(1, k)
// SSRAM slots on them. The count table is cleared at the setup's end, as the
// model's is.
module grid_sequencer #(
    parameter FLOAT = 1,
    parameter WIDTH = 32,
    parameter AW = 16,      // box index bits: up to 2^AW boxes
    parameter LAT = 2,      // SSRAM read latency in slots
    parameter M = 8,        // 2M - 1 lanes
    parameter CAW = 9,      // cell buffer address bits: cell_capacity <= 2^CAW
    parameter CW = 12,      // count table address bits: dims^3 <= 2^CW
    parameter EAW = 20,     // cell entry address bits (EAW > AW)
    parameter SPAN = 8      // cells a binned box may cover at most (max_span <= SPAN)
) (
    input  wire                 clk,
    input  wire                 reset,
    input  wire                 start,          // START: a sweep of `objects` boxes begins
    input  wire                 enable,         // a slot (low while the pipeline stalls)
    input  wire [AW:0]          objects,
    input  wire [8:0]           dims_setting,   // board.grid.dims (0: chosen from N)
    input  wire [31:0]          cell_size,      // board.grid.cell_size, binary32 (0: fitted)
    input  wire [CAW:0]         capacity,       // board.grid.cell_capacity
    input  wire [6:0]           max_span,       // board.grid.max_span
    input  wire [EAW:0]         entry_capacity, // cell entries the memory holds
    // The box store (SSRAM): words LAT slots after their read.
    output wire                 box_re,
    output wire [AW-1:0]        box_addr,
    input  wire [6*WIDTH-1:0]   box_words,
    // The cell loader: its loads, and its entry reads served from the lists.
    output wire                 load_start,
    output wire                 load_due,       // a load begins in the next slot (the cells' first, a tile's)
    output wire                 load_half,
    output wire [CAW:0]         load_count,
    output wire [EAW-1:0]       load_first,
    input  wire                 load_done,
    input  wire [EAW-1:0]       entry_addr,
    output wire [AW-1:0]        entry_word,     // LAT slots after its read
    output wire [95:0]          grid_lo,
    output wire [95:0]          grid_scale,
    output wire [8:0]           grid_dims,
    // The large sweep's streamed box (the row register): its words in each of its slots.
    output wire [6*WIDTH-1:0]   stream_words,
    // This slot: its kind (0 bubble, 1 sweep, 2 end) and window, the half the lanes read.
    output reg  [1:0]           slot_kind,
    output reg  [31:0]          window_row,
    output reg  [31:0]          window_column,
    output reg  [7:0]           window_lanes,
    output wire                 sweep_half,
    // Probes after the edge (GridClockedEngine's pass(), box(), cell(), tile(), waiting(), last_issue()).
    output reg  [3:0]           pass,
    output reg  [AW:0]          box,
    output reg  [CW-1:0]        cell_number,
    output reg  [AW:0]          tile,
    output reg                  waiting,
    output reg  [31:0]          last_row,
    output reg  [31:0]          last_column,
    output reg  [7:0]           last_lanes,
    // The grid registers (GridSweepStats).
    output reg  [AW:0]          large_boxes,
    output reg  [AW:0]          overflow_boxes,
    output reg  [AW:0]          excluded_boxes,
    output reg  [EAW:0]         cell_entries,
    output reg  [CW:0]          busy_cells,
    output reg  [47:0]          slots
);
    localparam [3:0] IDLE = 4'd0, BOUNDS = 4'd1, SETUP = 4'd2, COUNT = 4'd3, SCAN = 4'd4, PLACE = 4'd5,
                     CELLS = 4'd6, LARGE = 4'd7, DONE = 4'd8;
    localparam LANES = 2 * M - 1;
    localparam F = 4;                       // the cell function's stages
    localparam FILL = LAT + F;              // a binning pass's fill: GridSlots::pass(0)
    localparam GRID_SETUP = 16;             // GridConfig::kSetupSlots
    localparam FAW = 4;                     // the read-ahead FIFO: 16 >= FILL + 1 boxes for LAT <= 11
    localparam [1:0] BINNED = 2'd0, LARGE_BOX = 2'd1, EXCLUDED = 2'd2;
    localparam [31:0] FLT_MAX = 32'h7F7F_FFFF;

    // ---- Float helpers ----------------------------------------------------
    // IEEE a < b for numbers (no NaN): +-0 equal, else the sign-flipped order.
    function automatic less(input [31:0] a, input [31:0] b);
        reg [31:0] ka, kb;
        begin
            ka = a[31] ? ~a : a | 32'h8000_0000;
            kb = b[31] ? ~b : b | 32'h8000_0000;
            less = !(a[30:0] == 0 && b[30:0] == 0) && ka < kb;
        end
    endfunction
    // A stored word's key (NumberFormat::key): ordered as the format orders.
    function automatic [31:0] key(input [WIDTH-1:0] word);
        reg [31:0] w;
        begin
            w = 0;
            w[WIDTH-1:0] = word;
            if (FLOAT != 0) begin
                if (w == 32'h8000_0000) w = 0;
                key = w[31] ? ~w : w | 32'h8000_0000;
            end else begin
                key = w;
            end
        end
    endfunction
    // x * 0.5 rounded to nearest even, for finite x.
    function automatic [31:0] halve(input [31:0] x);
        reg [23:0] m;
        reg [23:0] r;
        begin
            if (x[30:23] > 8'd1) begin
                halve = {x[31], x[30:23] - 8'd1, x[22:0]};
            end else begin
                m = {x[30:23] != 0, x[22:0]};
                r = {1'b0, m[23:1]} + {23'b0, m[0] & m[1]};
                halve = {x[31], 7'b0, r};
            end
        end
    endfunction

    // ---- The sequencer's state --------------------------------------------
    reg [31:0] pass_slot;
    reg        end_issued;
    reg [AW:0] large_n;          // the large-box list's length
    reg [EAW:0] entries_n;       // cell entries counted
    reg [EAW:0] scanned;
    reg [CW:0] busy_n;
    reg [31:0] least [0:2], greatest [0:2];
    reg [31:0] lo [0:2], scale [0:2];
    reg [8:0] dims, dims_search;
    // Count and place: the box's slots left (0: the next box's first slot) and its data.
    reg [31:0] box_left;
    reg [49:0] held;             // {excluded, inverted, range hi z, y, x, lo z, y, x}
    reg [1:0] held_kind;
    // Cells: the busy cell swept and how many are loaded; the triangle's row and column.
    reg [CW:0] block, blocks_loaded;
    reg in_block, first_load;
    reg [31:0] row, column;
    // Large: the tile, its boxes, the streamed box's rank among the large ones and its columns.
    reg [AW:0] tile_begin, rank;
    reg [CAW:0] tile_count;
    reg [31:0] first_column, columns_left;

    wire [31:0] n_objects = {{(31-AW){1'b0}}, objects};
    wire [24:0] cells_cube = dims * dims * dims;   // up to 256^3
    wire [31:0] cells_total = {7'b0, cells_cube};

    // ---- Reading boxes: the bounds pass, and ahead of the count and place passes ----
    wire binning = pass == COUNT || pass == PLACE;
    reg [AW:0] issued, popped;                // boxes read ahead, boxes taken
    wire pop;                                 // a box's first slot takes its data
    wire [AW:0] outstanding = issued - popped - {{AW{1'b0}}, pop};
    wire read_ahead = binning && issued < objects && {{(31-AW){1'b0}}, outstanding} <= FILL;
    wire stream_read;                         // the large sweep reads its next streamed box
    wire [AW-1:0] stream_issued;
    assign box_re = (pass == BOUNDS && pass_slot < n_objects) || read_ahead || stream_read;
    assign box_addr = pass == BOUNDS ? pass_slot[AW-1:0] : pass == LARGE ? stream_issued : issued[AW-1:0];

    // Six cell-function units on the words LAT slots after a read; the
    // box's flags delayed to meet their cells F slots later.
    wire [47:0] cells_of;                     // hi z, y, x, lo z, y, x
    genvar b;
    generate
        for (b = 0; b < 6; b = b + 1) begin : g_bound
            grid_cell_function #(.FLOAT(FLOAT), .WIDTH(WIDTH)) unit (
                .clk(clk), .enable(enable), .word(box_words[b*WIDTH +: WIDTH]), .lo(lo[b % 3]),
                .scale(scale[b % 3]), .dims(dims), .cell_index(cells_of[b*8 +: 8]));
        end
    endgenerate
    reg excluded_now, inverted_now;
    integer a;
    always @* begin
        excluded_now = 0;
        inverted_now = 0;
        for (a = 0; a < 6; a = a + 1)
            if (FLOAT != 0 && {1'b0, box_words[a*WIDTH +: 31]} > 32'h7F80_0000) excluded_now = 1;
        for (a = 0; a < 3; a = a + 1)
            if (key(box_words[a*WIDTH +: WIDTH]) > key(box_words[(a+3)*WIDTH +: WIDTH])) inverted_now = 1;
    end
    reg [1:0] flags_delay [0:F-1];
    reg [LAT+F-1:0] ahead;                    // ahead[j]: a read-ahead box j + 1 slots after its read
    integer s;
    always @(posedge clk) if (enable) begin
        flags_delay[0] <= {excluded_now, inverted_now};
        for (s = 1; s < F; s = s + 1) flags_delay[s] <= flags_delay[s-1];
        ahead <= {ahead[LAT+F-2:0], read_ahead};
    end
    wire arriving = ahead[LAT+F-1];
    wire [49:0] arrival = {flags_delay[F-1], cells_of};
    reg [49:0] fifo [0:(1<<FAW)-1];
    reg [FAW:0] fifo_n;
    reg [FAW-1:0] fifo_head;
    wire [49:0] next_box = fifo_n != 0 ? fifo[fifo_head] : arrival;
    always @(posedge clk) begin
        if (start || (enable && !binning)) begin
            fifo_n <= 0;
            fifo_head <= 0;
            issued <= 0;
            popped <= 0;
        end else if (enable) begin
            if (read_ahead) issued <= issued + 1'b1;
            if (pop) popped <= popped + 1'b1;
            if (arriving && !(pop && fifo_n == 0)) fifo[fifo_head + fifo_n[FAW-1:0]] <= arrival;
            if (pop && fifo_n != 0) fifo_head <= fifo_head + 1'b1;
            fifo_n <= fifo_n + {{FAW{1'b0}}, arriving} - {{FAW{1'b0}}, pop};
        end
    end

    // ---- Count and place: this slot's box and its cells --------------------
    wire bin_slot = binning && pass_slot >= FILL;
    assign pop = bin_slot && box_left == 0;
    wire [49:0] data = pop ? next_box : held;
    wire [AW:0] this_box = pass_slot == FILL ? {(AW+1){1'b0}} : box;
    wire [1:0] place_kind;
    wire [1:0] this_kind = pop ? place_kind : held_kind;
    wire [7:0] lo_x = data[7:0], lo_y = data[15:8], lo_z = data[23:16];
    wire [7:0] hi_x = data[31:24], hi_y = data[39:32], hi_z = data[47:40];
    wire [8:0] cells_x = {1'b0, hi_x - lo_x} + 9'd1, cells_y = {1'b0, hi_y - lo_y} + 9'd1;
    wire [8:0] cells_z = {1'b0, hi_z - lo_z} + 9'd1;
    wire [26:0] cells_xyz = cells_x * cells_y * cells_z;
    wire [31:0] k = {5'b0, cells_xyz};
    wire excluded = data[49], inverted = data[48];
    wire candidate = !excluded && !inverted && k <= {25'b0, max_span};
    wire placing = pass == PLACE && this_kind == BINNED;
    wire [31:0] cells_taken = pass == COUNT ? (candidate ? k : 32'd0) : (placing ? k : 32'd0);
    wire [31:0] left = pop ? (cells_taken > 32'd1 ? cells_taken : 32'd1) : box_left;
    wire commit = bin_slot && left == 32'd1;
    // The box's cells, x fastest, and whether it fits.
    reg [SPAN*CW-1:0] box_cells;
    reg [SPAN-1:0] box_on;
    wire box_full;
    reg entries_fit;
    // The first cell's number, then steps: +1 along x, to the next row
    // (+dims less the row's span), to the next plane (+dims^2 less the rows').
    wire [7:0] span_x = hi_x - lo_x, span_y = hi_y - lo_y;
    wire [16:0] plane = dims * dims;
    wire [31:0] first_cell = {24'b0, lo_x} + dims * ({24'b0, lo_y} + dims * {24'b0, lo_z});
    wire [31:0] row_step = {23'b0, dims} - {24'b0, span_x};
    wire [31:0] plane_step = {15'b0, plane} - dims * {24'b0, span_y} - {24'b0, span_x};
    reg [7:0] x, y;
    /* verilator lint_off UNUSEDSIGNAL */
    reg [31:0] cell_address;  // a cell number in 32 bits, of which the table takes CW
    /* verilator lint_on UNUSEDSIGNAL */
    integer j;
    always @* begin
        x = lo_x;
        y = lo_y;
        cell_address = first_cell;
        entries_fit = {{(32-EAW-1){1'b0}}, entry_capacity - entries_n} >= k;
        for (j = 0; j < SPAN; j = j + 1) begin
            box_on[j] = j < k;
            box_cells[j*CW +: CW] = cell_address[CW-1:0];
            if (x != hi_x) begin
                x = x + 8'd1;
                cell_address = cell_address + 32'd1;
            end else if (y != hi_y) begin
                x = lo_x;
                y = y + 8'd1;
                cell_address = cell_address + row_step;
            end else begin
                x = lo_x;
                y = lo_y;
                cell_address = cell_address + plane_step;
            end
        end
    end
    wire room = entries_fit && !box_full;
    wire binned = candidate && room;

    // ---- Cells: this slot's busy cell ---------------------------------------
    wire block_starts = pass == CELLS && !in_block && blocks_loaded > block;
    wire in_block_now = in_block || block_starts;
    wire [31:0] row_now = block_starts ? 32'd0 : row;
    wire [31:0] column_now = block_starts ? 32'd1 : column;
    wire [CW-1:0] sweep_cell;
    wire [CAW:0] sweep_count;
    wire [31:0] cell_n = {{(31-CAW){1'b0}}, sweep_count};
    wire [31:0] cell_rest = cell_n - column_now;
    wire [7:0] cell_lanes = cell_rest < LANES ? cell_rest[7:0] : LANES[7:0];
    wire [31:0] column_next = column_now + LANES;
    wire triangle_done = column_next >= cell_n && row_now + 32'd2 >= cell_n;
    wire next_loads = block_starts && block + 1'b1 < busy_n;

    // ---- Large: this slot of the tile -----------------------------------------
    wire [31:0] lead = {{(31-CAW){1'b0}}, tile_count} + 3 * LAT + F;
    wire streaming = pass == LARGE && pass_slot >= lead;
    wire box_begins = streaming && box_left == 0;
    wire [1:0] stream_kind;
    wire [AW:0] after = rank + 1'b1;
    wire [AW:0] after_tile = after - tile_begin > {{(AW-CAW){1'b0}}, tile_count} ? {{(AW-CAW){1'b0}}, tile_count} : after - tile_begin;
    wire [31:0] first_now = !box_begins ? first_column
                          : stream_kind == BINNED ? 32'd0
                          : stream_kind == LARGE_BOX ? (after <= tile_begin ? 32'd0 : {{(31-AW){1'b0}}, after_tile})
                          : {{(31-CAW){1'b0}}, tile_count};
    wire [31:0] columns_now = box_begins ? {{(31-CAW){1'b0}}, tile_count} - first_now : columns_left;
    wire [31:0] stream_lanes = columns_now < LANES ? columns_now : LANES;
    wire stream_box_ends = columns_now <= LANES;   // q = 1: the box's slots end with its columns
    wire [AW:0] tile_next = tile_begin + {{(AW-CAW){1'b0}}, tile_count};
    wire [AW:0] tile_rest = large_n - tile_next;

    // ---- Large: the streamed boxes read ahead into the row register -------------
    // Box j is read at least LAT slots before its first slot (a tile's lead
    // leaves LAT slots after the loader's last read), a box a slot, never
    // more than LAT + 1 boxes ahead of the one streamed; they wait in a FIFO,
    // and the row register holds box j's words over its slots.
    localparam SAW = $clog2(LAT + 2);
    reg [AW:0] s_issued, s_popped;
    reg [6*WIDTH-1:0] s_fifo [0:(1<<SAW)-1];
    reg [SAW:0] s_n;
    reg [SAW-1:0] s_head;
    reg [6*WIDTH-1:0] row_register;
    wire s_arriving;                          // the words of a read LAT slots ago
    wire [31:0] s_ahead_limit = {{(31-AW){1'b0}}, s_popped} + {31'b0, box_begins} + LAT;
    assign stream_read = pass == LARGE && pass_slot + LAT >= lead && s_issued < objects &&
                         {{(31-AW){1'b0}}, s_issued} <= s_ahead_limit;
    assign stream_issued = s_issued[AW-1:0];
    wire [6*WIDTH-1:0] s_next = s_n != 0 ? s_fifo[s_head] : box_words;
    assign stream_words = box_begins ? s_next : row_register;
    generate
        if (LAT == 0) begin : g_stream_now
            assign s_arriving = stream_read;
        end else begin : g_stream_later
            reg [LAT-1:0] s_ahead;
            integer t;
            always @(posedge clk) begin
                if (start) begin
                    s_ahead <= 0;
                end else if (enable) begin
                    s_ahead[0] <= stream_read;
                    for (t = 1; t < LAT; t = t + 1) s_ahead[t] <= s_ahead[t-1];
                end
            end
            assign s_arriving = s_ahead[LAT-1];
        end
    endgenerate
    always @(posedge clk) begin
        if (start || (enable && (pass != LARGE || pass_slot == 0))) begin
            s_issued <= 0;
            s_popped <= 0;
            s_n <= 0;
            s_head <= 0;
        end else if (enable) begin
            if (stream_read) s_issued <= s_issued + 1'b1;
            if (box_begins) begin
                s_popped <= s_popped + 1'b1;
                row_register <= s_next;
            end
            if (s_arriving && !(box_begins && s_n == 0)) s_fifo[s_head + s_n[SAW-1:0]] <= box_words;
            if (box_begins && s_n != 0) s_head <= s_head + 1'b1;
            s_n <= s_n + {{SAW{1'b0}}, s_arriving} - {{SAW{1'b0}}, box_begins};
        end
    end

    // ---- The slot's kind and window --------------------------------------------
    always @* begin
        slot_kind = 2'd0;
        window_row = 0;
        window_column = 0;
        window_lanes = 0;
        if (pass == CELLS && in_block_now) begin
            slot_kind = 2'd1;
            window_row = row_now;
            window_column = column_now;
            window_lanes = cell_lanes;
        end else if (streaming && columns_now != 0) begin
            slot_kind = 2'd1;
            window_row = {{(31-AW){1'b0}}, box};
            window_column = first_now;
            window_lanes = stream_lanes[7:0];
        end else if (pass == DONE && !end_issued) begin
            slot_kind = 2'd2;
        end
    end
    assign sweep_half = pass == CELLS ? block[0] : 1'b0;

    // ---- The loader's loads and its entry reads ----------------------------------
    wire cells_load = pass == CELLS && (first_load || next_loads);
    wire [CW-1:0] load_block = first_load ? {CW{1'b0}} : block[CW-1:0] + 1'b1;
    wire tile_load = pass == LARGE && pass_slot == 0;
    assign load_start = enable && (cells_load || tile_load);
    assign load_due = (pass == CELLS && first_load) || (pass == LARGE && pass_slot == 0);
    assign load_half = cells_load ? load_block[0] : 1'b0;
    wire [CAW:0] busy_load_count;
    wire [EAW-1:0] busy_load_first;
    assign load_count = tile_load ? tile_count : busy_load_count;
    reg [EAW-1:0] tile_first;
    always @* begin
        tile_first = 0;
        tile_first[AW:0] = tile_begin;
    end
    assign load_first = tile_load ? tile_first : busy_load_first;
    wire [AW-1:0] entry_now;
    generate
        if (LAT == 0) begin : g_entry_now
            assign entry_word = entry_now;
        end else begin : g_entry_delayed
            reg [AW-1:0] entry_delay [0:LAT-1];
            integer e;
            always @(posedge clk) if (enable) begin
                entry_delay[0] <= entry_now;
                for (e = 1; e < LAT; e = e + 1) entry_delay[e] <= entry_delay[e-1];
            end
            assign entry_word = entry_delay[LAT-1];
        end
    endgenerate
    assign grid_lo = {lo[2], lo[1], lo[0]};
    assign grid_scale = {scale[2], scale[1], scale[0]};
    assign grid_dims = dims;

    // ---- Setup: the bounds' centres, the grid's size, extent and scale ----------
    wire [31:0] bound_value [0:5];
    wire [31:0] centre_sum [0:2];
    generate
        for (b = 0; b < 6; b = b + 1) begin : g_value
            if (FLOAT != 0) begin : g_float
                assign bound_value[b] = box_words[b*WIDTH +: WIDTH] == 32'h8000_0000 ? 32'b0 : box_words[b*WIDTH +: WIDTH];
            end else begin : g_fixed
                grid_code_float #(.WIDTH(WIDTH)) convert (.code(box_words[b*WIDTH +: WIDTH]), .value(bound_value[b]));
            end
        end
        for (b = 0; b < 3; b = b + 1) begin : g_centre
            grid_float_add add (.a(bound_value[b]), .b(bound_value[b+3]), .sum(centre_sum[b]));
        end
    endgenerate
    wire [31:0] setup_slot = pass_slot;
    wire [1:0] axis = setup_slot[1:0] - 2'd2;       // slots 10, 11, 12: axes 0, 1, 2
    wire [31:0] extent;
    grid_float_add extent_add (.a(greatest[axis]), .b({~least[axis][31], least[axis][30:0]}), .sum(extent));
    wire [31:0] dims_value;
    grid_code_float #(.WIDTH(9)) dims_float (.code(dims), .value(dims_value));
    wire fixed_cells = !cell_size[31] && cell_size[30:0] != 0;
    wire [31:0] quotient;
    grid_float_divide divide (.a(fixed_cells ? 32'h3F80_0000 : dims_value), .b(fixed_cells ? cell_size : extent),
                              .quotient(quotient));
    wire no_centre = less(greatest[axis], least[axis]);
    wire extent_usable = !extent[31] && extent[30:0] != 0 && extent[30:23] != 8'hFF;
    wire [8:0] candidate_dims = dims_search | (9'd1 << (4'd8 - setup_slot[3:0]));
    wire [35:0] candidate_boxes = 36'd16 * candidate_dims * candidate_dims * candidate_dims;

    // ---- The cell memory ---------------------------------------------------------
    wire count_commit = pass == COUNT && commit;
    wire [EAW:0] scan_count;
    grid_cell_memory #(.AW(AW), .CW(CW), .EAW(EAW), .CAW(CAW), .SPAN(SPAN)) memory (
        .clk(clk), .enable(enable), .clear(pass == SETUP && setup_slot == GRID_SETUP - 1),
        .box_cells(box_cells), .box_on(box_on), .capacity(capacity), .box_full(box_full),
        .count_box(count_commit && binned), .place_box(pass == PLACE && commit && placing),
        .box_index(this_box[AW-1:0]),
        .scan_cell(pass_slot[CW-1:0]), .scan_count(scan_count), .scan_write(pass == SCAN), .scan_base(scanned),
        .busy_write(pass == SCAN && scan_count >= 2), .busy_addr(busy_n[CW-1:0]),
        .sweep_busy(block[CW-1:0]), .sweep_cell(sweep_cell), .sweep_count(sweep_count),
        .load_busy(load_block), .load_first(busy_load_first), .load_count(busy_load_count),
        .kind_write(count_commit), .kind_addr(this_box[AW-1:0]),
        .kind_data(excluded ? EXCLUDED : binned ? BINNED : LARGE_BOX),
        .place_kind_addr(this_box[AW-1:0]), .place_kind(place_kind),
        .stream_kind_addr(box[AW-1:0]), .stream_kind(stream_kind),
        .large_write(count_commit && !excluded && !binned), .large_addr(large_n[AW-1:0]),
        .large_box(this_box[AW-1:0]),
        .entry_from_large(pass == LARGE), .entry_addr(entry_addr), .entry_box(entry_now));

    // ---- The slots ------------------------------------------------------------
    always @(posedge clk) begin
        if (reset) begin
            pass <= IDLE;
            box <= 0;
            cell_number <= 0;
            tile <= 0;
            waiting <= 0;
            last_row <= 0;
            last_column <= 0;
            last_lanes <= 0;
            box_left <= 0;
        end else if (start) begin
            pass <= objects < 2 ? DONE : BOUNDS;
            pass_slot <= 0;
            end_issued <= 0;
            waiting <= 0;
            slots <= 0;
            large_boxes <= 0;
            overflow_boxes <= 0;
            excluded_boxes <= 0;
            cell_entries <= 0;
            busy_cells <= 0;
            large_n <= 0;
            for (a = 0; a < 3; a = a + 1) begin
                least[a] <= FLT_MAX;
                greatest[a] <= {1'b1, FLT_MAX[30:0]};
            end
        end else if (enable) begin
            waiting <= 0;
            if (pass != IDLE && pass != DONE) slots <= slots + 1'b1;
            if (slot_kind == 2'd1) begin
                last_row <= window_row;
                last_column <= window_column;
                last_lanes <= window_lanes;
            end
            case (pass)
                BOUNDS: begin
                    pass_slot <= pass_slot + 1;
                    if (pass_slot + 32'd1 > LAT) begin
                        box <= pass_slot[AW:0] - LAT[AW:0];
                        if (!excluded_now) begin
                            for (a = 0; a < 3; a = a + 1) begin
                                // Infinite bounds, or a sum that overflows, give no centre.
                                if (bound_value[a][30:23] != 8'hFF && bound_value[a+3][30:23] != 8'hFF &&
                                    centre_sum[a][30:23] != 8'hFF) begin
                                    if (less(halve(centre_sum[a]), least[a])) least[a] <= halve(centre_sum[a]);
                                    if (less(greatest[a], halve(centre_sum[a]))) greatest[a] <= halve(centre_sum[a]);
                                end
                            end
                        end
                    end
                    if (pass_slot + 1 == n_objects + LAT) begin
                        pass <= SETUP;
                        pass_slot <= 0;
                        dims_search <= 0;
                    end
                end
                SETUP: begin
                    pass_slot <= pass_slot + 1;
                    if (setup_slot < 9) begin
                        if (candidate_dims <= 9'd256 && candidate_boxes <= {4'b0, n_objects}) dims_search <= candidate_dims;
                    end else if (setup_slot == 9) begin
                        dims <= dims_setting != 0 ? dims_setting : dims_search == 0 ? 9'd1 : dims_search;
                    end else if (setup_slot < 13) begin
                        lo[axis] <= no_centre ? 32'b0 : least[axis];
                        scale[axis] <= no_centre || !(fixed_cells || extent_usable) ? 32'b0 : quotient;
                    end else if (setup_slot == GRID_SETUP - 1) begin
                        entries_n <= 0;
                        pass <= COUNT;
                        pass_slot <= 0;
                        box_left <= 0;
                    end
                end
                COUNT, PLACE: begin
                    pass_slot <= pass_slot + 1;
                    if (bin_slot) begin
                        if (pop) begin
                            held <= next_box;
                            held_kind <= this_kind;
                        end
                        box_left <= left - 1;
                        if (pass_slot == FILL) box <= 0;
                        if (commit) begin
                            box <= this_box + 1'b1;
                            if (pass == COUNT) begin
                                if (excluded) excluded_boxes <= excluded_boxes + 1'b1;
                                if (candidate && !room) overflow_boxes <= overflow_boxes + 1'b1;
                            end
                            if (this_box + 1'b1 == objects) begin
                                pass_slot <= 0;
                                if (pass == COUNT) begin
                                    pass <= SCAN;
                                    large_boxes <= large_n + {{AW{1'b0}}, !excluded && !binned};
                                    large_n <= large_n + {{AW{1'b0}}, !excluded && !binned};
                                    cell_entries <= entries_n + (binned ? k[EAW:0] : {(EAW+1){1'b0}});
                                    scanned <= 0;
                                    busy_n <= 0;
                                end else begin
                                    enter_cells();
                                end
                            end else if (pass == COUNT) begin
                                if (!excluded && !binned) large_n <= large_n + 1'b1;
                                if (binned) entries_n <= entries_n + k[EAW:0];
                            end
                        end
                    end
                end
                SCAN: begin
                    pass_slot <= pass_slot + 1;
                    scanned <= scanned + scan_count;
                    if (scan_count >= 2) busy_n <= busy_n + 1'b1;
                    if (pass_slot + 1 == cells_total) begin
                        pass <= PLACE;
                        pass_slot <= 0;
                        box_left <= 0;
                    end
                end
                CELLS: begin
                    first_load <= 0;
                    if (block_starts) begin
                        in_block <= 1;
                        cell_number <= sweep_cell;
                    end
                    if (load_done) blocks_loaded <= blocks_loaded + 1'b1;
                    if (!in_block_now) begin
                        waiting <= 1;
                    end else begin
                        row <= row_now;
                        column <= column_next;
                        if (column_next >= cell_n) begin
                            row <= row_now + 1;
                            column <= row_now + 2;
                            if (triangle_done) begin
                                in_block <= 0;
                                block <= block + 1'b1;
                                if (block + 1'b1 == busy_n) enter_large();
                            end
                        end
                    end
                end
                LARGE: begin
                    pass_slot <= pass_slot + 1;
                    if (streaming) begin
                        if (box_begins && stream_kind == LARGE_BOX) rank <= after;
                        first_column <= first_now + stream_lanes;
                        columns_left <= columns_now - stream_lanes;
                        box_left <= stream_box_ends ? 32'd0 : 32'd1;
                        if (stream_box_ends) begin
                            box <= box + 1'b1;
                            if (box + 1'b1 == objects) begin
                                tile <= tile + 1'b1;
                                tile_begin <= tile_next;
                                if (tile_next < large_n) begin
                                    begin_tile(tile_rest);
                                end else begin
                                    pass <= DONE;
                                end
                            end
                        end
                    end
                end
                DONE: begin
                    if (!end_issued) begin
                        end_issued <= 1;
                        // The end marker's slot: the slots before it (GridSweepStats::slots).
                    end
                end
                default: ;
            endcase
        end
    end
    // The sweep's cells pass begins (the place pass's last slot): the first busy
    // cell loads from the next slot, or the large sweep begins when there is none.
    task enter_cells;
        begin
            busy_cells <= busy_n;
            block <= 0;
            blocks_loaded <= 0;
            in_block <= 0;
            if (busy_n == 0) begin
                enter_large();
            end else begin
                pass <= CELLS;
                first_load <= 1;
            end
        end
    endtask
    task enter_large;
        begin
            tile <= 0;
            tile_begin <= 0;
            if (large_n == 0) pass <= DONE;
            else begin_tile(large_n);
        end
    endtask
    task begin_tile(input [AW:0] rest);
        begin
            pass <= LARGE;
            pass_slot <= 0;
            tile_count <= rest > {{(AW-CAW){1'b0}}, capacity} ? capacity : rest[CAW:0];
            rank <= 0;
            box <= 0;
            box_left <= 0;
            first_column <= 0;
            columns_left <= 0;
        end
    endtask
endmodule
