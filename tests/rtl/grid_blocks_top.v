// The grid board's new blocks side by side under one Verilator model, for
// tests/rtl/grid_blocks_test.cpp to drive from C++ against their C++ models:
// the cell-function unit in float32, fixed32 (codes rounded to binary32) and
// fixed16 (the word's upper bits dropped), the one-cell filter of an m = 8
// board's fifteen lanes, and the cell loader filling an m = 2 cell buffer of
// 64 boxes a half from SSRAMs of latency 2 (1,024 boxes, 4,096 entries).
module grid_blocks_top (
    input  wire         clk,
    input  wire         enable,
    input  wire [31:0]  word,
    input  wire [31:0]  lo,
    input  wire [31:0]  scale,
    input  wire [8:0]   dims,
    output wire [7:0]   float32_cell,
    output wire [7:0]   fixed32_cell,
    output wire [7:0]   fixed16_cell,
    input  wire [14:0]  hits,
    input  wire [23:0]  here,
    input  wire [23:0]  row_first,
    input  wire [359:0] column_first,
    output wire [14:0]  kept,
    input  wire         load_start,
    input  wire         load_half,
    input  wire [6:0]   load_count,
    input  wire [11:0]  load_first_entry,
    input  wire [95:0]  grid_lo,
    input  wire [95:0]  grid_scale,
    output wire         entry_re,
    output wire [11:0]  entry_addr,
    input  wire [9:0]   entry_word,
    output wire         box_re,
    output wire [9:0]   box_addr,
    input  wire [191:0] box_words,
    output wire         load_write,
    output wire [5:0]   load_write_addr,
    output wire [225:0] load_write_data,
    output wire         load_busy,
    output wire         load_done,
    input  wire         read_half,
    input  wire [23:0]  read_addr,
    output wire [903:0] read_data
);
    grid_cell_function #(.FLOAT(1), .WIDTH(32)) float32_unit (
        .clk(clk), .enable(enable), .word(word), .lo(lo), .scale(scale), .dims(dims), .cell_index(float32_cell));
    grid_cell_function #(.FLOAT(0), .WIDTH(32)) fixed32_unit (
        .clk(clk), .enable(enable), .word(word), .lo(lo), .scale(scale), .dims(dims), .cell_index(fixed32_cell));
    grid_cell_function #(.FLOAT(0), .WIDTH(16)) fixed16_unit (
        .clk(clk), .enable(enable), .word(word[15:0]), .lo(lo), .scale(scale), .dims(dims), .cell_index(fixed16_cell));
    home_cell_filter #(.LANES(15)) filter (
        .hits(hits), .here(here), .row_first(row_first), .column_first(column_first), .kept(kept));
    wire write_half;
    cell_loader #(.FLOAT(1), .WIDTH(32), .AW(10), .EAW(12), .CAW(6), .LAT(2)) loader (
        .clk(clk), .enable(enable), .clear(1'b0), .start(load_start), .half(load_half), .count(load_count),
        .first_entry(load_first_entry), .lo(grid_lo), .scale(grid_scale), .dims(dims),
        .entry_re(entry_re), .entry_addr(entry_addr), .entry_word(entry_word),
        .box_re(box_re), .box_addr(box_addr), .box_words(box_words),
        .write(load_write), .write_half(write_half), .write_addr(load_write_addr), .write_data(load_write_data),
        .busy(load_busy), .done(load_done));
    cell_buffer #(.M(2), .EW(226), .CAW(6)) buffer (
        .clk(clk), .enable(enable), .read_half(read_half), .read_addr(read_addr), .read_data(read_data),
        .write(load_write), .write_half(write_half), .write_addr(load_write_addr), .write_data(load_write_data));
endmodule
