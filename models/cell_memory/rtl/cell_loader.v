// The grid board's cell loader (the loading half of the C++ CellBuffer,
// models/cell_memory/cell_buffer.h): a load of n boxes begun in slot 0 reads entry p (the box's
// index, from the cell entry list in SSRAM) in slot p, the box's six words
// by that index LAT slots later, and the three min bounds through three
// cell-function units (four stages), so box p is written in slot
// 2 LAT + 4 + p and the load ends in slot n + 2 LAT + 4 - 1: GridSlots::load(n)
// at one box a slot (six SSRAM banks). Slots are clock edges with enable;
// the SSRAMs' read pipelines hold with it (a ZBT SSRAM's clock enable).
module cell_loader #(
    parameter FLOAT = 1,
    parameter WIDTH = 32,
    parameter AW = 16,      // box index bits
    parameter EAW = 20,     // cell entry address bits
    parameter CAW = 9,      // cell buffer address bits: loads of up to 2^CAW boxes
    parameter LAT = 2       // SSRAM read latency in slots
) (
    input  wire                 clk,
    input  wire                 enable,
    input  wire                 clear,        // a new sweep: a load cut short by ABORT ends
    input  wire                 start,        // slot 0 of a load (while none is under way)
    input  wire                 half,         // the half it fills
    input  wire [CAW:0]         count,        // n >= 1
    input  wire [EAW-1:0]       first_entry,  // the list's first entry in SSRAM
    input  wire [95:0]          lo,           // the grid: x, y, z origins (binary32)
    input  wire [95:0]          scale,        // and scales
    input  wire [8:0]           dims,
    output wire                 entry_re,
    output wire [EAW-1:0]       entry_addr,
    input  wire [AW-1:0]        entry_word,   // LAT slots after its read
    output wire                 box_re,
    output wire [AW-1:0]        box_addr,
    input  wire [6*WIDTH-1:0]   box_words,    // LAT slots after its read
    output wire                 write,
    output reg                  write_half,
    output wire [CAW-1:0]       write_addr,
    output wire [24+AW+6*WIDTH-1:0] write_data,
    output wire                 busy,         // a load is under way (after its slot 0)
    output wire                 done          // this slot is the load's last
);
    localparam F = 4;                   // the cell function's stages
    localparam FILL = 2 * LAT + F;
    localparam SW = CAW + 8;            // slot counter bits (FILL <= 2*8+4 < 2^8 for LAT <= 8)
    localparam [SW-1:0] LAT_SLOTS = LAT[SW-1:0], FILL_SLOTS = FILL[SW-1:0];

    reg active;
    reg [SW-1:0] slot;                  // slots since the load began (slot 0 was start's)
    reg [CAW:0] n;
    reg [EAW-1:0] base;
    wire live = start | active;
    wire [SW-1:0] now = start ? {SW{1'b0}} : slot;
    wire [SW-1:0] boxes = start ? {{(SW-CAW-1){1'b0}}, count} : {{(SW-CAW-1){1'b0}}, n};

    assign entry_re = live && now < boxes;
    reg [EAW-1:0] offset;  // now, widened to an entry address
    integer k;
    always @* begin
        offset = 0;
        for (k = 0; k < SW && k < EAW; k = k + 1) offset[k] = now[k];
    end
    assign entry_addr = (start ? first_entry : base) + offset;
    wire latency_passed;
    generate
        if (LAT == 0) begin : g_flow_through
            assign latency_passed = 1'b1;
        end else begin : g_pipelined
            assign latency_passed = now >= LAT_SLOTS;
        end
    endgenerate
    assign box_re = live && latency_passed && now < boxes + LAT_SLOTS;
    assign box_addr = entry_word;
    assign write = live && now >= FILL_SLOTS && now < boxes + FILL_SLOTS;
    assign write_addr = now[CAW-1:0] - FILL_SLOTS[CAW-1:0];
    assign done = live && now == boxes + FILL_SLOTS - 1'b1;
    assign busy = active;

    always @(posedge clk) if (clear) begin
        active <= 0;
    end else if (enable) begin
        if (start) begin
            active <= !done;
            slot <= 1;
            n <= count;
            base <= first_entry;
            write_half <= half;
        end else if (active) begin
            slot <= slot + 1'b1;
            if (done) active <= 0;
        end
    end

    // The box's index waits LAT + F slots for its words' first cells, the words F.
    reg [AW-1:0] index_delay [0:LAT+F-1];
    reg [6*WIDTH-1:0] words_delay [0:F-1];
    integer s;
    always @(posedge clk) if (enable) begin
        index_delay[0] <= entry_word;
        for (s = 1; s < LAT + F; s = s + 1) index_delay[s] <= index_delay[s-1];
        words_delay[0] <= box_words;
        for (s = 1; s < F; s = s + 1) words_delay[s] <= words_delay[s-1];
    end

    wire [23:0] first;
    genvar a;
    generate
        for (a = 0; a < 3; a = a + 1) begin : g_axis
            grid_cell_function #(.FLOAT(FLOAT), .WIDTH(WIDTH)) unit (
                .clk(clk), .enable(enable), .word(box_words[a*WIDTH +: WIDTH]), .lo(lo[a*32 +: 32]),
                .scale(scale[a*32 +: 32]), .dims(dims), .cell_index(first[a*8 +: 8]));
        end
    endgenerate
    assign write_data = {first, index_delay[LAT+F-1], words_delay[F-1]};
endmodule
