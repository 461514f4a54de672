// The all-pairs address generator: port 0 holds row i, ports 1..2M-1 hold
// first, first+1, ..., first+2M-2. In the first cycle of row i first = i+1;
// each following cycle first advances by 2M-1 until a port has reached
// N-1; then i advances, until i = N-2. Ports past N-1 are invalid.
// AW address bits: up to 2^AW boxes.
module address_generator #(
    parameter M = 8,
    parameter AW = 9
) (
    input  wire                    clk,
    input  wire                    start,     // load N and begin at row 0
    input  wire                    enable,    // low while the pipeline holds
    input  wire [AW:0]             objects,
    output wire                    sweeping,  // addresses valid this cycle
    output wire [AW-1:0]           row,
    output wire [(2*M-1)*AW-1:0]   columns,   // port k's address at (k-1)*AW
    output wire [2*M-2:0]          valid      // bit k-1: port k holds a box
);
    localparam LANES = 2 * M - 1;
    reg [AW:0] n, i, first;
    assign sweeping = (n >= 2) && (i <= n - 2);
    assign row = i[AW-1:0];
    always @(posedge clk) begin
        if (start) begin
            n <= objects;
            i <= 0;
            first <= 1;
        end else if (enable && sweeping) begin
            if (first + LANES > n - 1) begin
                i <= i + 1;
                first <= i + 2;
            end else begin
                first <= first + LANES;
            end
        end
    end
    genvar k;
    generate
        for (k = 0; k < LANES; k = k + 1) begin : g_port
            wire [AW:0] address = first + k;
            assign columns[k*AW +: AW] = address[AW-1:0];
            assign valid[k] = sweeping && (address <= n - 1);
        end
    endgenerate
endmodule
