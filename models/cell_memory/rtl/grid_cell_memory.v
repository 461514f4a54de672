// The grid board's cell memory as the binning sequencer uses it (the C++
// CellTable, models/cell_memory/cell_table.h, and the sequencer's large-box
// list and box kinds): the count table (a cell's count, then its next entry),
// the cell entry lists, the busy-cell list, the large-box list and each box's
// kind. Register files here: a box's cells (up to SPAN) are read and written
// at once, in the slot the sequencer commits the box, where the model's board
// keeps them in SSRAM and spends the box's max(q, k) slots on them; the
// sequencer spends the same slots. Reads are combinational, writes at an
// enabled edge. `clear` empties the count table in one edge (a flag a cell).
module grid_cell_memory #(
    parameter AW = 16,
    parameter CW = 12,
    parameter EAW = 20,
    parameter CAW = 9,
    parameter SPAN = 8
) (
    input  wire                 clk,
    input  wire                 enable,
    input  wire                 clear,
    // A box's cells: count it in each, or place its index at each one's next entry.
    input  wire [SPAN*CW-1:0]   box_cells,
    input  wire [SPAN-1:0]      box_on,
    input  wire [CAW:0]         capacity,
    output reg                  box_full,       // some cell already holds `capacity` boxes
    input  wire                 count_box,
    input  wire                 place_box,
    input  wire [AW-1:0]        box_index,
    // The scan: a cell's count, replaced by its first entry; a busy cell listed.
    input  wire [CW-1:0]        scan_cell,
    output wire [EAW:0]         scan_count,
    input  wire                 scan_write,
    input  wire [EAW:0]         scan_base,
    input  wire                 busy_write,
    input  wire [CW-1:0]        busy_addr,
    // The busy list read twice: the cell swept, the cell loaded.
    input  wire [CW-1:0]        sweep_busy,
    output wire [CW-1:0]        sweep_cell,
    output wire [CAW:0]         sweep_count,
    input  wire [CW-1:0]        load_busy,
    output wire [EAW-1:0]       load_first,
    output wire [CAW:0]         load_count,
    // Each box's kind: written by the count pass, read by the place pass and the stream.
    input  wire                 kind_write,
    input  wire [AW-1:0]        kind_addr,
    input  wire [1:0]           kind_data,
    input  wire [AW-1:0]        place_kind_addr,
    output wire [1:0]           place_kind,
    input  wire [AW-1:0]        stream_kind_addr,
    output wire [1:0]           stream_kind,
    // The large-box list, and the loader's reads of it or of the entry lists.
    input  wire                 large_write,
    input  wire [AW-1:0]        large_addr,
    input  wire [AW-1:0]        large_box,
    input  wire                 entry_from_large,
    input  wire [EAW-1:0]       entry_addr,
    output wire [AW-1:0]        entry_box
);
    reg [EAW:0] counts [0:(1<<CW)-1];
    reg [(1<<CW)-1:0] written;               // cells written this sweep (the others count 0)
    reg [AW-1:0] entry_list [0:(1<<EAW)-1];
    reg [AW-1:0] large_list [0:(1<<AW)-1];
    reg [1:0] kinds [0:(1<<AW)-1];
    reg [CW-1:0] busy_cell [0:(1<<CW)-1];
    reg [EAW-1:0] busy_first [0:(1<<CW)-1];
    reg [CAW:0] busy_count [0:(1<<CW)-1];

    function automatic [EAW:0] count_of(input [CW-1:0] cell_address);
        count_of = written[cell_address] ? counts[cell_address] : {(EAW+1){1'b0}};
    endfunction

    integer j;
    reg [SPAN*(EAW+1)-1:0] box_counts;       // each cell's count (or next entry)
    always @* begin
        box_full = 0;
        for (j = 0; j < SPAN; j = j + 1) begin
            box_counts[j*(EAW+1) +: EAW+1] = count_of(box_cells[j*CW +: CW]);
            if (box_on[j] && box_counts[j*(EAW+1) +: EAW+1] >= {{(EAW-CAW){1'b0}}, capacity}) box_full = 1;
        end
    end
    assign scan_count = count_of(scan_cell);
    assign sweep_cell = busy_cell[sweep_busy];
    assign sweep_count = busy_count[sweep_busy];
    assign load_first = busy_first[load_busy];
    assign load_count = busy_count[load_busy];
    assign place_kind = kinds[place_kind_addr];
    assign stream_kind = kinds[stream_kind_addr];
    assign entry_box = entry_from_large ? large_list[entry_addr[AW-1:0]] : entry_list[entry_addr];

    always @(posedge clk) if (enable) begin
        if (clear) written <= 0;
        if (count_box || place_box) begin
            for (j = 0; j < SPAN; j = j + 1) if (box_on[j]) begin
                if (place_box) entry_list[box_counts[j*(EAW+1) +: EAW]] <= box_index;
                counts[box_cells[j*CW +: CW]] <= box_counts[j*(EAW+1) +: EAW+1] + 1'b1;
                written[box_cells[j*CW +: CW]] <= 1;
            end
        end
        if (scan_write) begin
            counts[scan_cell] <= scan_base;
            written[scan_cell] <= 1;
        end
        if (busy_write) begin
            busy_cell[busy_addr] <= scan_cell;
            busy_first[busy_addr] <= scan_base[EAW-1:0];
            busy_count[busy_addr] <= scan_count[CAW:0];
        end
        if (kind_write) kinds[kind_addr] <= kind_data;
        if (large_write) large_list[large_addr] <= large_box;
    end
endmodule
