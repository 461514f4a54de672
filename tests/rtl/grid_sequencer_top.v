// The grid board's binning sequencer with the blocks it drives, for
// tests/rtl/grid_sequencer_test.cpp to step edge by edge beside
// GridClockedEngine: the sequencer, the cell loader, and the box store (an
// SSRAM of LAT slots' read latency, written by the test between sweeps),
// whose read port the loader takes while it loads. Two instances: float32
// (m = 3, LAT 2) and fixed16 (m = 1, LAT 0).
module grid_sequencer_harness #(
    parameter FLOAT = 1,
    parameter WIDTH = 32,
    parameter M = 3,
    parameter LAT = 2
) (
    input  wire               clk,
    input  wire               reset,
    input  wire               start,
    input  wire               enable,
    input  wire [10:0]        objects,
    input  wire [8:0]         dims_setting,
    input  wire [31:0]        cell_size,
    input  wire [6:0]         capacity,
    input  wire [6:0]         max_span,
    input  wire [13:0]        entry_capacity,
    input  wire               store_write,
    input  wire [9:0]         store_addr,
    input  wire [6*WIDTH-1:0] store_words,
    output wire [1:0]         slot_kind,
    output wire [31:0]        window_row,
    output wire [31:0]        window_column,
    output wire [7:0]         window_lanes,
    output wire [3:0]         pass,
    output wire [10:0]        box,
    output wire [11:0]        cell_number,
    output wire [10:0]        tile,
    output wire               loading,        // a load under way or due (CellBuffer::loading)
    output wire               waiting,
    output wire [31:0]        last_row,
    output wire [31:0]        last_column,
    output wire [7:0]         last_lanes,
    output wire [8:0]         dims,
    output wire [95:0]        lo,
    output wire [95:0]        scale,
    output wire [10:0]        large_boxes,
    output wire [10:0]        overflow_boxes,
    output wire [10:0]        excluded_boxes,
    output wire [13:0]        cell_entries,
    output wire [12:0]        busy_cells,
    output wire [47:0]        slots
);
    localparam AW = 10, CAW = 6, CW = 12, EAW = 13;
    wire seq_re, loader_re, load_start, load_due, loader_busy, load_half, load_done, write, write_half, entry_re, sweep_half;
    wire [AW-1:0] seq_addr, loader_addr, entry_word;
    wire [CAW:0] load_count;
    wire [EAW-1:0] load_first, entry_addr;
    wire [CAW-1:0] write_addr;
    wire [24+AW+6*WIDTH-1:0] write_data;

    // The box store: the loader's reads while it loads, the sequencer's otherwise.
    reg [6*WIDTH-1:0] store [0:(1<<AW)-1];
    wire [AW-1:0] read_addr = loader_re ? loader_addr : seq_addr;
    wire [6*WIDTH-1:0] words;
    always @(posedge clk) if (store_write) store[store_addr] <= store_words;
    generate
        if (LAT == 0) begin : g_flow_through
            assign words = store[read_addr];
        end else begin : g_pipelined
            reg [6*WIDTH-1:0] delay [0:LAT-1];
            integer s;
            always @(posedge clk) if (enable) begin
                delay[0] <= store[read_addr];
                for (s = 1; s < LAT; s = s + 1) delay[s] <= delay[s-1];
            end
            assign words = delay[LAT-1];
        end
    endgenerate

    grid_sequencer #(.FLOAT(FLOAT), .WIDTH(WIDTH), .AW(AW), .LAT(LAT), .M(M), .CAW(CAW), .CW(CW), .EAW(EAW),
                     .SPAN(27)) sequencer (
        .clk(clk), .reset(reset), .start(start), .enable(enable), .objects(objects),
        .dims_setting(dims_setting), .cell_size(cell_size), .capacity(capacity), .max_span(max_span),
        .entry_capacity(entry_capacity),
        .box_re(seq_re), .box_addr(seq_addr), .box_words(words),
        
        .load_start(load_start), .load_due(load_due), .load_half(load_half), .load_count(load_count), .load_first(load_first),
        .load_done(load_done), .entry_addr(entry_addr), .entry_word(entry_word),
        .grid_lo(lo), .grid_scale(scale), .grid_dims(dims), .stream_words(),
        .slot_kind(slot_kind), .window_row(window_row), .window_column(window_column), .window_lanes(window_lanes),
        .sweep_half(sweep_half), .pass(pass), .box(box), .cell_number(cell_number), .tile(tile),
        .waiting(waiting), .last_row(last_row), .last_column(last_column), .last_lanes(last_lanes),
        .large_boxes(large_boxes), .overflow_boxes(overflow_boxes), .excluded_boxes(excluded_boxes),
        .cell_entries(cell_entries), .busy_cells(busy_cells), .slots(slots));
    cell_loader #(.FLOAT(FLOAT), .WIDTH(WIDTH), .AW(AW), .EAW(EAW), .CAW(CAW), .LAT(LAT)) loader (
        .clk(clk), .enable(enable), .clear(start), .start(load_start), .half(load_half), .count(load_count),
        .first_entry(load_first), .lo(lo), .scale(scale), .dims(dims),
        .entry_re(entry_re), .entry_addr(entry_addr), .entry_word(entry_word),
        .box_re(loader_re), .box_addr(loader_addr), .box_words(words),
        .write(write), .write_half(write_half), .write_addr(write_addr), .write_data(write_data),
        .busy(loader_busy), .done(load_done));
    assign loading = loader_busy || load_due;
endmodule

// The two instances side by side in one Verilator model: f_ float32 (m = 3,
// SSRAM latency 2) and x_ fixed16 (m = 1, latency 0).
module grid_sequencer_top (
    input  wire clk,
    input  wire reset,
    input  wire            f_start,
    input  wire            f_enable,
    input  wire [10:0]     f_objects,
    input  wire [8:0]      f_dims_setting,
    input  wire [31:0]     f_cell_size,
    input  wire [6:0]      f_capacity,
    input  wire [6:0]      f_max_span,
    input  wire [13:0]     f_entry_capacity,
    input  wire            f_store_write,
    input  wire [9:0]      f_store_addr,
    input  wire [191:0]    f_store_words,
    output wire [1:0]      f_slot_kind,
    output wire [31:0]     f_window_row,
    output wire [31:0]     f_window_column,
    output wire [7:0]      f_window_lanes,
    output wire [3:0]      f_pass,
    output wire [10:0]     f_box,
    output wire [11:0]     f_cell_number,
    output wire [10:0]     f_tile,
    output wire            f_loading,
    output wire            f_waiting,
    output wire [31:0]     f_last_row,
    output wire [31:0]     f_last_column,
    output wire [7:0]      f_last_lanes,
    output wire [8:0]      f_dims,
    output wire [95:0]     f_lo,
    output wire [95:0]     f_scale,
    output wire [10:0]     f_large_boxes,
    output wire [10:0]     f_overflow_boxes,
    output wire [10:0]     f_excluded_boxes,
    output wire [13:0]     f_cell_entries,
    output wire [12:0]     f_busy_cells,
    output wire [47:0]     f_slots,
    input  wire            x_start,
    input  wire            x_enable,
    input  wire [10:0]     x_objects,
    input  wire [8:0]      x_dims_setting,
    input  wire [31:0]     x_cell_size,
    input  wire [6:0]      x_capacity,
    input  wire [6:0]      x_max_span,
    input  wire [13:0]     x_entry_capacity,
    input  wire            x_store_write,
    input  wire [9:0]      x_store_addr,
    input  wire [95:0]     x_store_words,
    output wire [1:0]      x_slot_kind,
    output wire [31:0]     x_window_row,
    output wire [31:0]     x_window_column,
    output wire [7:0]      x_window_lanes,
    output wire [3:0]      x_pass,
    output wire [10:0]     x_box,
    output wire [11:0]     x_cell_number,
    output wire [10:0]     x_tile,
    output wire            x_loading,
    output wire            x_waiting,
    output wire [31:0]     x_last_row,
    output wire [31:0]     x_last_column,
    output wire [7:0]      x_last_lanes,
    output wire [8:0]      x_dims,
    output wire [95:0]     x_lo,
    output wire [95:0]     x_scale,
    output wire [10:0]     x_large_boxes,
    output wire [10:0]     x_overflow_boxes,
    output wire [10:0]     x_excluded_boxes,
    output wire [13:0]     x_cell_entries,
    output wire [12:0]     x_busy_cells,
    output wire [47:0]     x_slots
);
    grid_sequencer_harness #(.FLOAT(1), .WIDTH(32), .M(3), .LAT(2)) f (.clk(clk), .reset(reset), .start(f_start), .enable(f_enable), .objects(f_objects), .dims_setting(f_dims_setting), .cell_size(f_cell_size), .capacity(f_capacity), .max_span(f_max_span), .entry_capacity(f_entry_capacity), .store_write(f_store_write), .store_addr(f_store_addr), .store_words(f_store_words), .slot_kind(f_slot_kind), .window_row(f_window_row), .window_column(f_window_column), .window_lanes(f_window_lanes), .pass(f_pass), .box(f_box), .cell_number(f_cell_number), .tile(f_tile), .loading(f_loading), .waiting(f_waiting), .last_row(f_last_row), .last_column(f_last_column), .last_lanes(f_last_lanes), .dims(f_dims), .lo(f_lo), .scale(f_scale), .large_boxes(f_large_boxes), .overflow_boxes(f_overflow_boxes), .excluded_boxes(f_excluded_boxes), .cell_entries(f_cell_entries), .busy_cells(f_busy_cells), .slots(f_slots));
    grid_sequencer_harness #(.FLOAT(0), .WIDTH(16), .M(1), .LAT(0)) x (.clk(clk), .reset(reset), .start(x_start), .enable(x_enable), .objects(x_objects), .dims_setting(x_dims_setting), .cell_size(x_cell_size), .capacity(x_capacity), .max_span(x_max_span), .entry_capacity(x_entry_capacity), .store_write(x_store_write), .store_addr(x_store_addr), .store_words(x_store_words), .slot_kind(x_slot_kind), .window_row(x_window_row), .window_column(x_window_column), .window_lanes(x_window_lanes), .pass(x_pass), .box(x_box), .cell_number(x_cell_number), .tile(x_tile), .loading(x_loading), .waiting(x_waiting), .last_row(x_last_row), .last_column(x_last_column), .last_lanes(x_last_lanes), .dims(x_dims), .lo(x_lo), .scale(x_scale), .large_boxes(x_large_boxes), .overflow_boxes(x_overflow_boxes), .excluded_boxes(x_excluded_boxes), .cell_entries(x_cell_entries), .busy_cells(x_busy_cells), .slots(x_slots));
endmodule
