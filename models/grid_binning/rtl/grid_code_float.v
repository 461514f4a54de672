// A fixed-point board's stored bound as the binning stage sees it: the
// unsigned WIDTH-bit code rounded to binary32, nearest even (exact up to 24
// bits), as the C++ NumberFormat::fixed_value gives it. Combinational: the
// sequencer's bounds unit holds one a bound. The cell-function unit's first
// stage computes the same inline (so that its stored synthesis row stays the
// one Yosys gives for it: ABC's result shifts with how the design is written).
module grid_code_float #(
    parameter WIDTH = 32
) (
    input  wire [WIDTH-1:0] code,
    output wire [31:0]      value
);
    function automatic [5:0] leading_zeros32(input [31:0] x);
        integer k;
        begin
            leading_zeros32 = 6'd32;
            for (k = 0; k < 32; k = k + 1) if (x[k]) leading_zeros32 = 6'd31 - k[5:0];
        end
    endfunction
    reg [31:0] wide;
    always @* begin
        wide = 0;
        wide[WIDTH-1:0] = code;
    end
    // The leading one at bit 31, then 24 bits kept; rounding up carries into
    // the exponent field by itself.
    wire [5:0] zeros = leading_zeros32(wide);
    wire [31:0] norm = wide << zeros[4:0];
    wire [7:0] exponent = 8'd158 - {2'b0, zeros};
    wire round_up = norm[7] & ((|norm[6:0]) | norm[8]);
    assign value = norm[31] ? {1'b0, exponent, norm[30:8]} + {31'b0, round_up} : 32'b0;
endmodule
